#pragma once

// A byte mask of the scan as one bit a voxel, 32 along i to a texel of an R32UI 3D texture (bit
// i % 32 of texel (i / 32, j, k)): an eighth of an R8UI texture's memory (33 MiB rather than 262
// MiB at 512x512x1000, on llvmpipe host memory beside the scan's), for one shift and mask more
// in the pass that fills a brick's speeds once (solver/barrier_speed.glsl's voxelBit).
#include "gpu/gl_handle.hpp"

#include <cstdint>
#include <glm/glm.hpp>
#include <span>

namespace steerseg::solver::detail {

// The texture of `mask` (non-zero = set, i fastest), bound to texture unit `unit`; an empty
// texture when no voxel is set. std::invalid_argument naming `what` for a span of another size.
// Needs a current context; the caller guards its GL state.
gpu::Texture uploadVoxelBits(std::span<const std::uint8_t> mask, const glm::ivec3& dims, int unit,
                             const char* what);

} // namespace steerseg::solver::detail
