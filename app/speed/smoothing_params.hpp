#pragma once

// Plain data (no GL): the session, the command line and the report name it.

namespace steerseg::speed {

// Edge-preserving smoothing of the scan before the speed reads it: gradient anisotropic
// diffusion (Perona-Malik, shaders/speed/diffuse.comp). iterations = 0: none (the speed reads
// the raw scan). conductance K in real units: neighbour differences well below K diffuse,
// differences well above it (edges) are kept.
struct SmoothingParams {
    int iterations = 0;
    float conductance = 0.0F;
    bool operator==(const SmoothingParams&) const = default;
};

// ITK's stable time step for this explicit scheme in 3D, 1 / 2^(3+1).
inline constexpr float kDiffusionTimeStep = 0.0625F;
inline constexpr int kMaxSmoothingIterations = 1000;

// Throws std::invalid_argument (one line) unless 0 <= iterations <= kMaxSmoothingIterations
// and, when smoothing, the conductance is a finite number > 0.
void validateSmoothing(const SmoothingParams& params);

} // namespace steerseg::speed
