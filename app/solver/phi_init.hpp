#pragma once

// Initial level sets on the CPU (run once, not per iteration): both solvers start from these.

#include "model/level_set_params.hpp"

#include <cstdint>
#include <glm/glm.hpp>
#include <span>
#include <vector>

namespace steerseg::solver {

// Clamped signed distance (voxel units, negative inside) to the boundary of a binary mask
// (non-zero = inside): phi = +-(distance to the nearest voxel of the other label - 0.5), so the
// zero level set lies half-way between inside and outside voxel centres. Throws
// std::invalid_argument when mask.size() does not match dims.
std::vector<float> maskToPhi(std::span<const std::uint8_t> mask, const glm::ivec3& dims);

// maskToPhi lightly smoothed (a [1 2 1] / 4 filter twice along each axis, about a voxel's
// Gaussian), every voxel kept on its side (|phi| >= 0.05): the same mask at the voxel centres,
// but a level set whose zero surface rounds the voxels' staircase off between them, so a mask
// (a --mask file, a resumed session) is drawn as smoothly as a level set the solver evolved.
std::vector<float> smoothMaskPhi(std::span<const std::uint8_t> mask, const glm::ivec3& dims);

// 1 where lo <= value <= hi. Throws std::invalid_argument for lo > hi or NaN bounds.
std::vector<std::uint8_t> thresholdMask(std::span<const float> values, float lo, float hi);

// Union (add) or difference (remove) of a dense phi with a sphere, clamped. In voxel steps: the
// reference solver's scans are isotropic, where a sphere round in mm is a ball of voxels.
void applySphere(std::vector<float>& phi, const glm::ivec3& dims, const model::Sphere& sphere,
                 bool add);

// 1 where phi < 0.
std::vector<std::uint8_t> insideMask(std::span<const float> phi);

} // namespace steerseg::solver
