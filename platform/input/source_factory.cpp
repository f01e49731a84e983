#include "platform/input/sources.hpp"

namespace steerseg::platform::input {

std::unique_ptr<RawSource> openSource(const DeviceSpec& spec, std::string& problem) {
    switch (spec.kind) {
    case DeviceSpec::Kind::Shuttle:
    case DeviceSpec::Kind::Radial:
        return openHidSource(spec, problem);
    case DeviceSpec::Kind::PowerMate:
        return openEvdevSource(spec, problem);
    case DeviceSpec::Kind::GpioInput:
    case DeviceSpec::Kind::GpioLed:
        return openGpioSource(spec, problem);
    }
    problem = spec.name + ": unknown device kind";
    return nullptr;
}

} // namespace steerseg::platform::input
