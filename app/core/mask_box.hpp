#pragma once

// The box a mask's voxels lie in: what a pass over a mask needs to visit (its smooth field, its
// depth) and the challenge's box prompt drawn from a label (bench/steering).
#include "core/volume.hpp"

#include <cstdint>
#include <glm/glm.hpp>
#include <optional>
#include <span>
#include <vector>

namespace steerseg {

struct MaskBox {
    glm::ivec3 lo{0}; // inclusive voxel indices
    glm::ivec3 hi{0};
};

// The box of the non-zero voxels of a mask on a grid of `dims` (one byte a voxel, i fastest);
// nullopt when it has none. std::invalid_argument when the mask's size is not the grid's.
std::optional<MaskBox> maskBox(const glm::ivec3& dims, std::span<const std::uint8_t> mask);

// The box grown by `margin` voxels on every side, within a grid of `dims`.
MaskBox grownWithin(const MaskBox& box, int margin, const glm::ivec3& dims);

// The box's voxel count along each axis.
inline glm::ivec3 boxDims(const MaskBox& box) {
    return box.hi - box.lo + 1;
}

// `mask` (on a grid of `dims`) over `box`, on the box's own grid (i fastest): `inside` where the
// mask is non-zero, else `outside`. The box lies in the grid.
template <typename T>
std::vector<T> cropMask(const glm::ivec3& dims, std::span<const std::uint8_t> mask,
                        const MaskBox& box, T inside, T outside) {
    const glm::ivec3 sub = boxDims(box);
    std::vector<T> out(static_cast<std::size_t>(sub.x) * static_cast<std::size_t>(sub.y) *
                       static_cast<std::size_t>(sub.z));
    std::size_t v = 0;
    for (int k = box.lo.z; k <= box.hi.z; ++k) {
        for (int j = box.lo.y; j <= box.hi.y; ++j) {
            const std::uint8_t* row = mask.data() + linearIndex(dims, box.lo.x, j, k);
            for (int i = 0; i < sub.x; ++i, ++v) {
                out[v] = row[i] != 0 ? inside : outside;
            }
        }
    }
    return out;
}

} // namespace steerseg
