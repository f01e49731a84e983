#pragma once

// Opening the live devices behind raw_source.hpp, and listing what is attached (for
// `steerseg input-monitor` and the panel). Each open throws nothing: it returns nullptr and a
// one-line problem that names the node and, for a permission error, the group or udev rule
// that is missing.
#include "platform/input/device_spec.hpp"
#include "platform/input/raw_source.hpp"

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

namespace steerseg::platform::input {

struct AttachedDevice {
    std::string kind; // "hid", "evdev", "gpiochip"
    std::string node; // "/dev/hidraw3", "/dev/input/event7", "/dev/gpiochip0"
    std::uint16_t vendorId = 0;
    std::uint16_t productId = 0;
    std::uint16_t usagePage = 0;
    std::uint16_t usage = 0;
    std::string description; // product string, evdev name or chip label
};

// hid/hid_source.cpp (hidapi, hidraw backend): the first record read is the HidDescriptor.
std::unique_ptr<RawSource> openHidSource(const DeviceSpec& spec, std::string& problem);
std::vector<AttachedDevice> listHidDevices();
// evdev/evdev_source.cpp: setIndicator drives the PowerMate LED through EV_MSC/MSC_PULSELED.
// A node that can only be read opens with `problem` set as a warning (the LED stays off).
std::unique_ptr<RawSource> openEvdevSource(const DeviceSpec& spec, std::string& problem);
std::vector<AttachedDevice> listEvdevDevices();
// gpio/gpio_source.cpp (libgpiod 1.6 behind gpio/gpio_chip.hpp, so a 2.x adapter can
// replace it): GpioInput yields GpioEdge records; GpioLed takes setIndicator (pulsing blinks).
std::unique_ptr<RawSource> openGpioSource(const DeviceSpec& spec, std::string& problem);
std::vector<AttachedDevice> listGpioChips();

// Opens the source for a spec's kind.
std::unique_ptr<RawSource> openSource(const DeviceSpec& spec, std::string& problem);

} // namespace steerseg::platform::input
