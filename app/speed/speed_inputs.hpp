#pragma once

#include "gpu/gl.hpp"
#include "speed/speed_kind.hpp"

namespace steerseg::speed {

// What the solver's data term reads (shaders/solver/speed_threshold.glsl), as borrowed R32F 3D
// textures on the scan's grid that must outlive their use by the solver:
//   intensity  I in real units: the smoothed scan (smoothScan), or 0 for the raw scan
//   factor     Edge: g (edgeFactor); Classify: P(inside) - P(outside); unused for Threshold
struct SpeedInputs {
    SpeedKind kind = SpeedKind::Threshold;
    GLuint intensity = 0;
    GLuint factor = 0;
};

// Throws std::invalid_argument when a kind that reads the factor texture has none.
void validateSpeedInputs(const SpeedInputs& inputs);

} // namespace steerseg::speed
