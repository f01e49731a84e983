#pragma once

#include "gpu/gl.hpp"
#include "model/speed_kind.hpp"

#include <glm/glm.hpp>

namespace steerseg::speed {

// What the data term reads (shaders/speed/data_speed.glsl: the solver's passes, and the slice
// views' speed view, so that what the operator sees is what moves the front), as borrowed R32F
// 3D textures on the scan's grid that must outlive their use:
//   intensity  I in real units: the smoothed scan (smoothScan), or 0 for the raw scan
//   factor     Edge: g (edgeFactor); Classify: P(inside) - P(outside); unused for Threshold
//   onDemand   Classify only: when it names a forest, `factor` holds the speed only where the
//              solver has evaluated it (ClassifierSpeed's Evaluation::OnDemand), and the solver
//              evaluates each brick with this forest, over the features of I, before it first
//              reads it
//   withinWindow  Classify only: bounded by the threshold's window T +- eps on I (and by a
//              correction's tissue window near it), as data_speed.glsl's classifyWithin
struct OnDemandForest {
    GLuint nodes = 0; // SSBO of speed::ForestNode; 0: no forest, the factor is complete
    GLuint roots = 0; // SSBO of each tree's root node index
    int trees = 0;
    int maxDepth = 0;
    GLuint place = 0;     // the place vote's 3D texture (speed/place_vote)
    glm::ivec3 stride{1}; // the features' step (classifierFeatureStride)
};

struct SpeedInputs {
    model::SpeedKind kind = model::SpeedKind::Threshold;
    GLuint intensity = 0;
    GLuint factor = 0;
    OnDemandForest onDemand;
    bool withinWindow = false;
};

// Throws std::invalid_argument when a kind that reads the factor texture has none, for a
// forest given with another kind than classify or without its roots, trees, depth or place vote,
// and for a window bound on another kind than classify.
void validateSpeedInputs(const SpeedInputs& inputs);

// Binds I (inputs.intensity, or `rawScan`, the exact scan texture, when 0) and the factor to
// the texture units a shader's data_speed.glsl reads (DATA_SPEED_INTENSITY_UNIT and
// DATA_SPEED_FACTOR_UNIT). Leaves the active texture unit changed.
void bindSpeedTextures(const SpeedInputs& inputs, GLuint rawScan, int intensityUnit,
                       int factorUnit);

} // namespace steerseg::speed
