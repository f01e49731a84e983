#pragma once

#include "gpu/gl.hpp"
#include "speed/speed_kind.hpp"

namespace steerseg::speed {

// What the data term reads (shaders/speed/data_speed.glsl: the solver's passes, and the slice
// views' speed view, so that what the operator sees is what moves the front), as borrowed R32F
// 3D textures on the scan's grid that must outlive their use:
//   intensity  I in real units: the smoothed scan (smoothScan), or 0 for the raw scan
//   factor     Edge: g (edgeFactor); Classify: P(inside) - P(outside); unused for Threshold
struct SpeedInputs {
    SpeedKind kind = SpeedKind::Threshold;
    GLuint intensity = 0;
    GLuint factor = 0;
};

// Throws std::invalid_argument when a kind that reads the factor texture has none.
void validateSpeedInputs(const SpeedInputs& inputs);

// Binds I (inputs.intensity, or `rawScan`, the exact scan texture, when 0) and the factor to
// the texture units a shader's data_speed.glsl reads (DATA_SPEED_INTENSITY_UNIT and
// DATA_SPEED_FACTOR_UNIT). Leaves the active texture unit changed.
void bindSpeedTextures(const SpeedInputs& inputs, GLuint rawScan, int intensityUnit,
                       int factorUnit);

} // namespace steerseg::speed
