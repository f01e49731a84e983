#pragma once

// A configured input device: what kind of decoder it needs and how to find it. The kiosk
// builds these from the config's [[input.devices]] entries; platform/ knows nothing of the
// config file.
#include <cstdint>
#include <string>

namespace steerseg::platform::input {

struct DeviceSpec {
    enum class Kind {
        Shuttle,   // Contour ShuttleXpress / ShuttlePRO v2 over hidraw (hidapi)
        Radial,    // a HID System Multi-Axis Controller with a Dial (descriptor-parsed)
        PowerMate, // Griffin PowerMate through its evdev node
        GpioInput, // a pedal or panel button on a GPIO line (libgpiod)
        GpioLed,   // a status LED on a GPIO output line
    };
    Kind kind = Kind::Shuttle;
    std::string name; // prefix of its control names ("shuttle" -> "shuttle_jog")
    // HID: matched by vendor/product id, and by usage page/usage where non-zero.
    std::uint16_t vendorId = 0;
    std::uint16_t productId = 0;
    std::uint16_t usagePage = 0;
    std::uint16_t usage = 0;
    // evdev: a node ("/dev/input/event5") or, when empty, the first device whose vendor and
    // product id match.
    std::string path;
    // GPIO: chip ("gpiochip0" or a label) and line (a name, or an offset as digits).
    std::string chip;
    std::string line;
    bool activeLow = false;
    double debounceSeconds = 0.02;
};

} // namespace steerseg::platform::input
