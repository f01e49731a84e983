#include "platform/input/evdev/powermate_led.hpp"

#include <algorithm>

namespace steerseg::platform::input {

std::int32_t packPowerMateLed(const PowerMateLed& led) {
    const auto brightness = static_cast<std::uint32_t>(std::clamp(led.brightness, 0, 255));
    const auto speed = static_cast<std::uint32_t>(std::clamp(led.pulseSpeed, 0, 510));
    const auto table = static_cast<std::uint32_t>(std::clamp(led.pulseTable, 0, 2));
    const std::uint32_t value = brightness | (speed << 8U) | (table << 17U) |
                                (led.pulseAsleep ? 1U << 19U : 0U) |
                                (led.pulseAwake ? 1U << 20U : 0U);
    return static_cast<std::int32_t>(value);
}

PowerMateLed powerMateLedFor(Indicator indicator) {
    PowerMateLed led;
    switch (indicator) {
    case Indicator::Off:
        break;
    case Indicator::Steady:
        led.brightness = 255;
        break;
    case Indicator::Pulsing:
        led.pulseAwake = true;
        break;
    }
    return led;
}

} // namespace steerseg::platform::input
