#include "platform/input/decoders.hpp"

namespace steerseg::platform::input {

std::unique_ptr<Decoder> makeDecoder(const DeviceSpec& spec) {
    switch (spec.kind) {
    case DeviceSpec::Kind::Shuttle:
        return makeShuttleDecoder(spec);
    case DeviceSpec::Kind::Radial:
        return makeRadialDecoder(spec);
    case DeviceSpec::Kind::PowerMate:
        return makePowerMateDecoder(spec);
    case DeviceSpec::Kind::GpioInput:
        return makeGpioLineDecoder(spec);
    case DeviceSpec::Kind::GpioLed:
        return nullptr;
    }
    return nullptr;
}

} // namespace steerseg::platform::input
