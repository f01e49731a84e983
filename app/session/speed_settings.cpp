#include "session/speed_settings.hpp"

#include "speed/edge_factor.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

namespace steerseg::session {

namespace {

void checkExamples(const std::vector<model::Sphere>& spheres, const glm::ivec3& dims,
                   const char* what) {
    for (const model::Sphere& s : spheres) {
        try {
            model::validateSphere(s, dims);
        } catch (const std::invalid_argument& e) {
            throw std::invalid_argument(std::string(what) + ": " + e.what());
        }
    }
}

} // namespace

void validateSpeedSettings(const SpeedSettings& settings, const glm::ivec3& dims) {
    speed::validateSmoothing(settings.smoothing);
    if (settings.kind == model::SpeedKind::Edge) {
        speed::validateKappa(settings.kappa);
    }
    if (settings.kind == model::SpeedKind::Classify &&
        (settings.inside.empty() || settings.outside.empty())) {
        throw std::invalid_argument(
            "the classify speed needs at least one inside and one outside example");
    }
    if (settings.withinWindow && settings.kind != model::SpeedKind::Classify) {
        throw std::invalid_argument("only the classify speed is bounded by the window");
    }
    if (!std::isfinite(settings.placeReach) || settings.placeReach < 0.0) {
        throw std::invalid_argument("the classify speed's place reach must be finite and >= 0");
    }
    if (settings.box) {
        model::validateBox(*settings.box, dims);
    }
    checkExamples(settings.inside, dims, "inside example");
    checkExamples(settings.outside, dims, "outside example");
}

} // namespace steerseg::session
