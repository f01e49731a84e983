#pragma once

// The Griffin PowerMate's LED command, the value of the EV_MSC/MSC_PULSELED event its kernel
// driver (drivers/input/misc/powermate.c) unpacks: bits 0-7 static brightness, 8-16 pulse
// speed (0-510, 255 = standard), 17-18 pulse table (0-2), 19 pulse while asleep, 20 pulse
// while awake.
#include "platform/input/raw_source.hpp"

#include <cstdint>

namespace steerseg::platform::input {

struct PowerMateLed {
    int brightness = 0;   // 0..255
    int pulseSpeed = 255; // 0..510
    int pulseTable = 0;   // 0..2
    bool pulseAsleep = false;
    bool pulseAwake = false;
};

// Out-of-range fields are clamped, so the value never sets bits the driver reads as another field.
std::int32_t packPowerMateLed(const PowerMateLed& led);
// Off: dark; Steady: full brightness; Pulsing: the standard pulse while awake.
PowerMateLed powerMateLedFor(Indicator indicator);

} // namespace steerseg::platform::input
