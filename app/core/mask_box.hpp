#pragma once

// The box a mask's voxels lie in: what a pass over a mask needs to visit (its smooth field, its
// depth) and the challenge's box prompt drawn from a label (bench/steering).
#include <cstdint>
#include <glm/glm.hpp>
#include <optional>
#include <span>

namespace steerseg {

struct MaskBox {
    glm::ivec3 lo{0}; // inclusive voxel indices
    glm::ivec3 hi{0};
};

// The box of the non-zero voxels of a mask on a grid of `dims` (one byte a voxel, i fastest);
// nullopt when it has none. std::invalid_argument when the mask's size is not the grid's.
std::optional<MaskBox> maskBox(const glm::ivec3& dims, std::span<const std::uint8_t> mask);

} // namespace steerseg
