#pragma once

// Which speed drives the surface and what it needs, as plain data (docs/speed.md): the command
// line and the kiosk fill it, Session::setSpeed turns it into textures on the GPU.
#include "model/box.hpp"
#include "model/level_set_params.hpp"
#include "model/speed_kind.hpp"
#include "speed/smoothing_params.hpp"

#include <functional>
#include <glm/glm.hpp>
#include <optional>
#include <string_view>
#include <vector>

namespace steerseg::session {

struct SpeedSettings {
    model::SpeedKind kind = model::SpeedKind::Threshold;
    speed::SmoothingParams smoothing; // what the speed's I is: the scan smoothed this way
    float kappa = 0.0F;               // edge: real units per voxel, > 0
    // classify: the operator's examples, voxel indices and radii in voxels.
    std::vector<model::Sphere> inside;
    std::vector<model::Sphere> outside;
    // classify: bounded by the threshold's window T +- eps (speed::SpeedInputs::withinWindow).
    bool withinWindow = false;
    // classify: how far, in its radii, an example decides where appearance is unsure
    // (speed::ClassifierParams::placeReach, the kiosk's [speed] classify_place_reach); 0: never.
    double placeReach = 3.0;
    // Every kind: the operator's box, which the surface does not leave (model::Box).
    std::optional<model::Box> box;
    bool operator==(const SpeedSettings&) const = default;
};

// Throws std::invalid_argument (one line) for settings no speed can run with: smoothing out of
// range, edge without kappa > 0, classify without an inside and an outside example, an example
// that does not fit the scan (dims), a window bound on another speed than classify, a place
// reach that is not finite or is negative, a box validateBox refuses.
void validateSpeedSettings(const SpeedSettings& settings, const glm::ivec3& dims);

// Seconds spent making the speed's textures (GPU work finished).
struct SpeedTiming {
    double preprocessingSeconds = 0.0; // smoothing and the edge factor
    // The classifier's training (its evaluation is the solver's, where the front goes).
    double trainingSeconds = 0.0;
};

// Progress of Session::setSpeed: the stage ("smoothing", "edge factor", "training") and its
// steps done out of total (smoothing: per iteration).
using SpeedProgress = std::function<void(std::string_view stage, int done, int total)>;

} // namespace steerseg::session
