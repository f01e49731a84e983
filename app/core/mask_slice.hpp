#pragma once

// The boundary of a mask (as runs) on one plane of constant index: what a slice view draws of a
// structure that is not the solver's level set (docs/structures.md). The edges lie on the
// voxels' faces, in voxel-index coordinates, so a view maps them as it maps any voxel position.
#include "core/mask_runs.hpp"

#include <cstdint>
#include <glm/vec3.hpp>
#include <vector>

namespace steerseg {

struct MaskEdge {
    glm::dvec3 a{0.0};
    glm::dvec3 b{0.0};
};

// The plane `index` along index axis `axis` (0 i, 1 j, 2 k) of a mask on a grid of `dims`,
// i fastest: one byte per voxel of the plane, u the lower and v the higher of the other two
// axes, u fastest. Empty runs: all zero. std::invalid_argument for a mask of another size or a
// plane outside the grid.
std::vector<std::uint8_t> maskPlane(const MaskRuns& mask, const glm::ivec3& dims, int axis,
                                    int index);

// The faces between inside and outside voxels of that plane (the grid's edge counts as
// outside), each a segment at the plane's index on the slice axis.
std::vector<MaskEdge> planeBoundary(const std::vector<std::uint8_t>& plane, const glm::ivec3& dims,
                                    int axis, int index);

} // namespace steerseg
