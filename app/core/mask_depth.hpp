#pragma once

// How deep a voxel lies in a mask, in mm on the scan's grid: the click robot's deepest voxel
// (bench/steering) and the part of a surface an erase's run may not take back
// (workflow: docs/steering.md, "An erase's run, watched and taken back").
#include <cstdint>
#include <glm/glm.hpp>
#include <span>
#include <vector>

namespace steerseg {

// Exact Euclidean distance in mm from every voxel to the nearest voxel where `sites` is non-zero
// (0 on a site; Felzenszwalb and Huttenlocher's separable transform). With `beyondIsSite` the
// voxels just outside the grid count as sites too (a region's distance to its boundary, the
// grid's edge included); without, a grid with no site gives +infinity everywhere. Masks are
// flat, i fastest, one byte a voxel.
std::vector<float> distanceToSitesMm(const glm::ivec3& dims, const glm::dvec3& spacingMm,
                                     std::span<const std::uint8_t> sites, bool beyondIsSite);

// 1 where `mask` holds a voxel whose centre lies more than `depthMm` from every voxel outside
// it, else 0; the grid's edge is no boundary (a surface there has nothing beyond it to withdraw
// to). Computed over the mask's bounding box grown by a voxel, so its cost follows the mask.
// std::invalid_argument for a mask of another size or a depth that is negative or not finite.
std::vector<std::uint8_t> deeperThan(const glm::ivec3& dims, const glm::dvec3& spacingMm,
                                     std::span<const std::uint8_t> mask, double depthMm);

} // namespace steerseg
