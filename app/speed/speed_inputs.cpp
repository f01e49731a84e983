#include "speed/speed_inputs.hpp"

#include <stdexcept>
#include <string>

namespace steerseg::speed {

void validateSpeedInputs(const SpeedInputs& inputs) {
    if (inputs.kind != SpeedKind::Threshold && inputs.factor == 0) {
        throw std::invalid_argument(std::string("speed ") +
                                    std::string(speedKindName(inputs.kind)) +
                                    " needs its factor texture");
    }
}

} // namespace steerseg::speed
