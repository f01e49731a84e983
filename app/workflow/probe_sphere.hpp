#pragma once

// A probe's sphere in voxels: what the workflow keeps as a classify example and the kiosk's
// engine as the edge speed's noise region, so both mean the same voxels.
#include "model/level_set_params.hpp"

#include <algorithm>
#include <cmath>
#include <glm/glm.hpp>

namespace steerseg::workflow {

// The probe is round in mm, as a sphere is (model::Sphere): its radius in voxels along the
// finest axis, at least `minRadius` and at most the scan's diagonal (the solver's bound on a
// sphere; a huge probe radius stays finite).
inline model::Sphere probeSphere(const glm::dvec3& voxel, double radiusMm,
                                 const glm::dvec3& spacing, const glm::ivec3& dims,
                                 double minRadius) {
    const double finest = std::min({spacing.x, spacing.y, spacing.z});
    const double r = finest > 0.0 && std::isfinite(finest) ? radiusMm / finest : radiusMm;
    const double diagonal = glm::length(glm::dvec3(dims));
    return {glm::vec3(voxel), static_cast<float>(std::clamp(r, minRadius, diagonal))};
}

} // namespace steerseg::workflow
