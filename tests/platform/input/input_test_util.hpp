#pragma once

// Helpers of the input decoder tests: hex to bytes, records, and running a decoder.
#include "platform/input/decoder.hpp"

#include <cstdint>
#include <cstdio>
#include <string>
#include <string_view>
#include <vector>

namespace steerseg::test {

// The Surface Dial over Bluetooth (045e:091b), 277 bytes, as documented in
// github.com/WOA-Project/documentation_surface_dial (DefaultHIDDescriptor.md).
inline constexpr const char* kSurfaceDialHex = R"(
05 01 09 0E A1 01 85 01 05 0D 09 21 A1 02 15 00
25 01 75 01 95 01 A1 00 05 09 09 01 81 02 05 0D
09 33 81 02 95 06 81 03 A1 02 05 01 09 37 16 01
80 26 FF 7F 75 10 95 01 81 06 35 00 46 10 0E 15
00 26 10 0E 09 48 B1 02 45 00 C0 55 0E 65 11 46
00 00 26 00 00 09 30 81 42 09 31 46 00 00 26 00
00 81 42 05 0D 09 48 15 3A 25 3A 75 08 55 0F 35
3A 45 3A 81 03 55 00 65 00 35 00 45 00 05 0E 09
01 A1 02 15 00 26 FF 00 09 24 B1 42 09 24 91 42
15 01 25 07 09 20 B1 42 09 21 91 42 25 0A 09 28
B1 42 75 10 26 D0 07 09 25 B1 42 09 25 91 42 85
02 75 20 17 37 00 01 00 27 37 00 01 00 09 22 B1
02 09 11 A1 02 05 0A 95 03 09 03 09 04 09 05 75
08 15 00 25 FF B1 02 C0 05 0E 09 10 A1 02 05 0A
95 01 15 03 25 03 36 03 10 46 03 10 09 03 B1 02
15 04 25 04 36 04 10 46 04 10 09 04 B1 02 15 05
25 05 36 04 10 46 04 10 09 05 B1 02 35 00 45 00
C0 C0 C0 C0 C0)";

// Microsoft's sample radial controller descriptor ("Windows radial controller sample report
// descriptors", Windows hardware design docs): a 1-bit button, then a 15-bit signed Dial at
// bit 1, X, Y and a constant Width; report id 1.
inline constexpr const char* kMicrosoftSampleRadialHex = R"(
05 01 09 0e a1 01 85 01 05 0d 09 21 a1 00 05 09 09 01 95 01 75 01 15 00 25 01 81 02
05 01 09 37 95 01 75 0f 55 0f 65 14 36 f0 f1 46 10 0e 16 f0 f1 26 10 0e 81 06
09 30 75 10 55 0d 65 13 35 00 46 c0 5d 15 00 26 ff 7f 81 02 09 31 46 b0 36 81 02
05 0d 09 48 36 b8 0b 46 b8 0b 16 b8 0b 26 b8 0b 81 03 c0 c0)";

inline std::vector<std::uint8_t> hexBytes(std::string_view text) {
    std::vector<std::uint8_t> bytes;
    int high = -1;
    for (const char c : text) {
        int v = -1;
        if (c >= '0' && c <= '9') {
            v = c - '0';
        } else if (c >= 'a' && c <= 'f') {
            v = c - 'a' + 10;
        } else if (c >= 'A' && c <= 'F') {
            v = c - 'A' + 10;
        } else {
            continue; // spaces and line breaks between bytes
        }
        if (high < 0) {
            high = v;
        } else {
            bytes.push_back(static_cast<std::uint8_t>(high * 16 + v));
            high = -1;
        }
    }
    return bytes;
}

inline platform::input::RawRecord hidReport(double t, std::vector<std::uint8_t> bytes) {
    platform::input::RawRecord r;
    r.kind = platform::input::RawRecord::Kind::HidReport;
    r.time = t;
    r.bytes = std::move(bytes);
    return r;
}

inline platform::input::RawRecord hidDescriptor(double t, std::vector<std::uint8_t> bytes) {
    platform::input::RawRecord r = hidReport(t, std::move(bytes));
    r.kind = platform::input::RawRecord::Kind::HidDescriptor;
    return r;
}

inline platform::input::RawRecord evdev(double t, int type, int code, int value) {
    platform::input::RawRecord r;
    r.kind = platform::input::RawRecord::Kind::Evdev;
    r.time = t;
    r.type = static_cast<std::uint16_t>(type);
    r.code = static_cast<std::uint16_t>(code);
    r.value = value;
    return r;
}

inline platform::input::RawRecord gpioEdge(double t, bool active) {
    platform::input::RawRecord r;
    r.kind = platform::input::RawRecord::Kind::GpioEdge;
    r.time = t;
    r.active = active;
    return r;
}

inline platform::input::RawRecord plugRecord(double t, bool plugged) {
    platform::input::RawRecord r;
    r.kind = plugged ? platform::input::RawRecord::Kind::Plugged
                     : platform::input::RawRecord::Kind::Unplugged;
    r.time = t;
    return r;
}

// The events as short text, one per event, for readable expectations:
// "shuttle_jog step 1", "shuttle_ring pos -0.429", "pedal press", "pedal release".
inline std::vector<std::string> describe(const std::vector<platform::input::ControlEvent>& events) {
    using Kind = platform::input::ControlEvent::Kind;
    std::vector<std::string> out;
    for (const auto& e : events) {
        switch (e.kind) {
        case Kind::Step:
            out.push_back(e.control + " step " + std::to_string(e.steps));
            break;
        case Kind::Position: {
            char text[32];
            std::snprintf(text, sizeof text, "%.3f", e.position);
            out.push_back(e.control + " pos " + text);
            break;
        }
        case Kind::Press:
            out.push_back(e.control + " press");
            break;
        case Kind::Release:
            out.push_back(e.control + " release");
            break;
        }
    }
    return out;
}

inline std::vector<platform::input::ControlEvent>
feedAll(platform::input::Decoder& d, const std::vector<platform::input::RawRecord>& records) {
    std::vector<platform::input::ControlEvent> out;
    for (const auto& r : records) {
        d.feed(r, out);
    }
    return out;
}

} // namespace steerseg::test
