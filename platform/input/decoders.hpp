#pragma once

// The decoder of each device kind (decoder.hpp). Each is implemented beside its source:
// hid/ (shuttle, radial), evdev/ (PowerMate), gpio/ (debounced lines).
#include "platform/input/decoder.hpp"
#include "platform/input/device_spec.hpp"

#include <memory>

namespace steerseg::platform::input {

// Contour ShuttleXpress and ShuttlePRO v2: `<name>_ring` (Position, -1..1 from the signed
// ring position -7..7, a Position 0 when it springs back), `<name>_jog` (Step: the wrapping
// 8-bit counter as signed steps), `<name>_button1`.. (Press/Release).
std::unique_ptr<Decoder> makeShuttleDecoder(const DeviceSpec& spec);
// A HID radial controller: waits for the HidDescriptor record, finds the Dial and button
// fields by parsing it; `<name>_turn` (Step), `<name>_press` (Press/Release).
std::unique_ptr<Decoder> makeRadialDecoder(const DeviceSpec& spec);
// Griffin PowerMate evdev stream: REL_DIAL -> `<name>_turn` (Step), BTN_0 -> `<name>_press`.
std::unique_ptr<Decoder> makePowerMateDecoder(const DeviceSpec& spec);
// A GPIO input line with software debounce: edges closer than spec.debounceSeconds collapse
// into one change; `<name>` (Press/Release; a held pedal stays pressed).
std::unique_ptr<Decoder> makeGpioLineDecoder(const DeviceSpec& spec);

// The decoder for a spec's kind; nullptr for kinds that take no input (GpioLed).
std::unique_ptr<Decoder> makeDecoder(const DeviceSpec& spec);

} // namespace steerseg::platform::input
