#pragma once

// The command line's --probe (docs/speed.md "How --probe chooses"): the speed's parameters
// from a region the operator marks as the structure, by rules from the image only.
#include "core/volume.hpp"
#include "model/level_set_params.hpp"

#include <cstddef>

namespace steerseg::session {

struct SpeedProbe {
    double mean = 0.0;   // real units
    double stddev = 0.0; // of the intensities (structure and noise)
    // The noise: RMS of the differences between face-neighbour voxels both in the region,
    // over sqrt(2) (white noise of std s has neighbour differences of std s * sqrt(2)). Smooth
    // structure inside the region barely raises it, unlike stddev.
    double noise = 0.0;
    std::size_t count = 0;
    // Suggestions: T = mean and eps = max(kEpsFactor * stddev, kEpsFloor), as the kiosk's
    // probe (session::suggestSpeed, the shipped config's eps floor);
    // conductance = kConductanceFactor * noise and kappa = kKappaFactor * noise, with
    // noise at least kNoiseFloor.
    double T = 0.0;
    double eps = 0.0;
    double conductance = 0.0;
    double kappa = 0.0;
};

inline constexpr double kEpsFactor = 2.0;
inline constexpr double kEpsFloor = 10.0;
inline constexpr double kConductanceFactor = 3.0;
inline constexpr double kKappaFactor = 1.0;
// The noise the suggestions assume at least (real units, a quarter of the eps floor).
inline constexpr double kNoiseFloor = 2.5;

// Voxels whose centres lie inside the sphere (voxel indices and a radius along the finest axis,
// like --seed: model::Sphere). std::invalid_argument when the sphere does not fit the scan or
// holds fewer than 2 voxels.
SpeedProbe probeSpeed(const Volume& volume, const model::Sphere& sphere);

} // namespace steerseg::session
