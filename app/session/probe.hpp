#pragma once

#include "core/volume.hpp"

#include <glm/glm.hpp>

namespace steerseg::session {

// Whether a probe leaves out one stray voxel where Grubbs' test finds one
// (core/single_outlier.hpp): what the speed's T and eps come from should (one voxel of contrast
// in a small probe sets the spread); a tissue's level, a mean over a ball, need not.
enum class Stray { Keep, LeaveOut };

// Intensity statistics (real units) of the voxels whose centres lie within `radiusMm` of a
// point given in voxel indices (the probe of any view). count = 0 if the sphere misses the
// volume.
struct ProbeStats {
    double mean = 0.0;
    double stddev = 0.0;     // population standard deviation of the voxels counted
    std::size_t count = 0;   // voxels counted
    std::size_t leftOut = 0; // 1 where the test left a voxel out
};
ProbeStats probe(const Volume& volume, const glm::dvec3& index, double radiusMm,
                 Stray stray = Stray::LeaveOut);

// The speed function's parameters a probe suggests: T = mean, eps = stddev * factor.
struct SuggestedSpeed {
    double T = 0.0;
    double eps = 0.0;
};
SuggestedSpeed suggestSpeed(const ProbeStats& stats, double factor = 2.0);

} // namespace steerseg::session
