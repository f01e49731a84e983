#pragma once

#include "core/volume.hpp"

#include <glm/glm.hpp>

namespace steerseg::session {

// Intensity statistics (real units) of the voxels whose centres lie within `radiusMm` of a
// point given in voxel indices (the probe of any view). count = 0 if the sphere misses the
// volume.
struct ProbeStats {
    double mean = 0.0;
    double stddev = 0.0;
    std::size_t count = 0;
};
ProbeStats probe(const Volume& volume, const glm::dvec3& index, double radiusMm);

// The speed function's parameters a probe suggests: T = mean, eps = stddev * factor.
struct SuggestedSpeed {
    double T = 0.0;
    double eps = 0.0;
};
SuggestedSpeed suggestSpeed(const ProbeStats& stats, double factor = 2.0);

} // namespace steerseg::session
