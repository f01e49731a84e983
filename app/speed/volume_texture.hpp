#pragma once

#include "gpu/gl_handle.hpp"

#include <glm/glm.hpp>

namespace steerseg::speed {

// An immutable R32F 3D texture on the scan's grid, nearest filtering (read by texelFetch,
// written by imageStore). Throws std::runtime_error naming `what` when the GPU cannot hold it.
gpu::Texture createVolumeTexture(const glm::ivec3& dims, const char* what);

// Whether `texture` is a 3D texture of R32F and `dims` (0, a deleted name or a 2D texture: no).
// Binds it at SPEED_SOURCE_UNIT: the caller holds a gpu::GlStateGuard.
bool isVolumeTexture(GLuint texture, const glm::ivec3& dims);

// Runs compute `program` over dims in 4^3 groups, reading `source` (SPEED_SOURCE_UNIT) and
// writing `target` (SPEED_OUT_IMAGE_UNIT); the caller holds a gpu::GlStateGuard and has set
// the program's other uniforms.
void runVolumePass(GLuint program, GLuint source, GLuint target, const glm::ivec3& dims);

} // namespace steerseg::speed
