#pragma once

// One undecoded piece of input as a device delivers it: a HID report (or the report
// descriptor read when the device opens), one evdev event, one GPIO edge. Live sources
// (sources.hpp), recordings (the recording file) and session scripts all produce these, and
// the same decoders (decoders.hpp) turn them into control events, so a recording replays
// through exactly the code the device runs through.
#include <cstdint>
#include <string>
#include <vector>

namespace steerseg::platform::input {

struct RawRecord {
    enum class Kind {
        HidDescriptor, // bytes: the report descriptor, sent once when the device opens
        HidReport,     // bytes: one input report as hidapi returns it (report id first
                       // when the descriptor uses report ids)
        Evdev,         // type, code, value of one struct input_event
        GpioEdge,      // active: the line's new logical level (active_low applied)
        Unplugged,     // the device went away (the source said Gone, or the hotplug monitor)
        Plugged,       // the device came back and was opened again
    };
    Kind kind = Kind::HidReport;
    double time = 0.0;  // seconds, monotonic (the recording's or the script's clock)
    std::string device; // the configured device name: "shuttle", "powermate", "pedal"
    std::vector<std::uint8_t> bytes;
    std::uint16_t type = 0;
    std::uint16_t code = 0;
    std::int32_t value = 0;
    bool active = false;
};

} // namespace steerseg::platform::input
