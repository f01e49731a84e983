#pragma once

#include "core/volume.hpp"

namespace steerseg {

// The built-in sample scan: a deterministic MR-like head phantom so the main job and tests run
// with no data. uint16, 128 x 128 x 96 voxels, 1.0 x 1.0 x 1.5 mm. Structures (real units):
//   background ~ 20, "scalp/skin" shell ~ 250, "brain" ellipsoid ~ 420,
//   a bright "lesion" sphere ~ 800 (centre voxel (80, 56, 52), radius 12 mm),
//   dark "ventricles" ~ 120, plus Gaussian-like noise (sigma ~ 15).
// Each voxel holds the mean of the tissue over its extent, as a scanner's does (partial volume),
// so the boundaries are smooth at the voxel's scale.
Volume makeSamplePhantom();

struct PhantomLesion {
    int i = 80, j = 56, k = 52;
    double radiusMm = 12.0;
    double intensity = 800.0;
};
inline constexpr PhantomLesion kPhantomLesion{};

} // namespace steerseg
