#include "speed/speed_inputs.hpp"

#include <stdexcept>
#include <string>

namespace steerseg::speed {

void validateSpeedInputs(const SpeedInputs& inputs) {
    if (inputs.kind != model::SpeedKind::Threshold && inputs.factor == 0) {
        throw std::invalid_argument(std::string("speed ") +
                                    std::string(model::speedKindName(inputs.kind)) +
                                    " needs its factor texture");
    }
    const OnDemandForest& f = inputs.onDemand;
    if (f.nodes != 0 && (inputs.kind != model::SpeedKind::Classify || f.roots == 0 || f.trees < 1 ||
                         f.maxDepth < 1 || f.place == 0)) {
        throw std::invalid_argument(
            "a speed evaluated on demand needs the classify kind and a whole forest");
    }
    if (inputs.withinWindow && inputs.kind != model::SpeedKind::Classify) {
        throw std::invalid_argument("only the classify speed is bounded by the window");
    }
}

void bindSpeedTextures(const SpeedInputs& inputs, GLuint rawScan, int intensityUnit,
                       int factorUnit) {
    glActiveTexture(GL_TEXTURE0 + static_cast<GLenum>(intensityUnit));
    glBindTexture(GL_TEXTURE_3D, inputs.intensity != 0 ? inputs.intensity : rawScan);
    glActiveTexture(GL_TEXTURE0 + static_cast<GLenum>(factorUnit));
    glBindTexture(GL_TEXTURE_3D, inputs.factor);
}

} // namespace steerseg::speed
