#pragma once

// How far a segmentation agrees with a reference label on the same grid: the accuracy figure
// of `segment --reference`, the accuracy benchmark and scripted sessions' `dice` steps.
#include "core/volume.hpp"

#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

namespace steerseg {

struct MaskOverlap {
    std::size_t mask = 0;      // voxels inside the segmentation
    std::size_t reference = 0; // voxels of the reference label
    std::size_t both = 0;
    // 2|A and B| / (|A| + |B|); two empty sets agree (1).
    [[nodiscard]] double dice() const {
        return mask + reference == 0
                   ? 1.0
                   : 2.0 * static_cast<double>(both) / static_cast<double>(mask + reference);
    }
};

// The segmentation's voxels are the mask's non-zero ones (for a Volume by maskInside's rule); the
// reference's are those whose real value rounds to `label`, or every non-zero one when label < 0.
// Throws std::invalid_argument with one line when the grids differ in size or a voxel is NaN.
MaskOverlap maskOverlap(std::span<const std::uint8_t> mask, const Volume& reference, int label);
MaskOverlap maskOverlap(const Volume& mask, const Volume& reference, int label);
// The reference's voxels by the same rule: 1 where it counts as inside, else 0.
std::vector<std::uint8_t> referenceVoxels(const Volume& reference, int label);

// Voxels where two masks of `dims` differ that are not on the reference's surface (a face
// neighbour with the other label): float rounding may move a surface by a voxel, a wrong speed
// or solver further. The GPU numerics check's rule and the solver agreement tests'.
std::size_t differencesOffSurface(const glm::ivec3& dims, std::span<const std::uint8_t> a,
                                  std::span<const std::uint8_t> reference);

} // namespace steerseg
