// The PowerMate and GPIO line decoders on arbitrary bytes read as a stream of events: each
// 4-byte group is (type, code, value, time step). Types are folded onto the few the kernel
// sends (EV_SYN, EV_KEY, EV_REL, EV_MSC) and codes onto a range holding REL_DIAL, BTN_0 and
// SYN_DROPPED, so the fuzzer spends its time where the decoders branch. The GPIO decoder takes
// the value's low bit as the line level and is ticked on the same clock.
#include "fuzz_input_checks.hpp"
#include "platform/input/decoders.hpp"

#include <cstdint>
#include <linux/input-event-codes.h>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    using namespace steerseg::platform::input;
    DeviceSpec knobSpec;
    knobSpec.kind = DeviceSpec::Kind::PowerMate;
    knobSpec.name = "powermate";
    DeviceSpec lineSpec;
    lineSpec.kind = DeviceSpec::Kind::GpioInput;
    lineSpec.name = "pedal";
    lineSpec.debounceSeconds = 0.02;
    auto knob = makeDecoder(knobSpec);
    auto line = makeDecoder(lineSpec);
    steerseg::fuzz::HeldControls held;
    std::vector<ControlEvent> out;
    static constexpr std::uint16_t kTypes[] = {EV_SYN, EV_KEY, EV_REL, EV_MSC};
    double t = 0.0;
    for (std::size_t at = 0; at + 4 <= size; at += 4) {
        RawRecord r;
        r.time = (t += data[at + 3] * 0.001);
        if (data[at] == 0xFF) {
            r.kind = RawRecord::Kind::Unplugged;
        } else {
            r.kind = RawRecord::Kind::Evdev;
            r.type = kTypes[data[at] & 3U];
            r.code = (data[at + 1] & 0x80U) != 0
                         ? static_cast<std::uint16_t>(BTN_0 + (data[at + 1] & 7U))
                         : data[at + 1];
            r.value = static_cast<std::int8_t>(data[at + 2]);
        }
        knob->feed(r, out);
        RawRecord edge = r;
        if (r.kind == RawRecord::Kind::Evdev) {
            edge.kind = RawRecord::Kind::GpioEdge;
            edge.active = (data[at + 2] & 1U) != 0;
        }
        line->tick(t, out);
        line->feed(edge, out);
    }
    line->tick(t + 1.0, out);
    held.check(out);
    if (knob->takeProblems().size() > 33 || line->takeProblems().size() > 33) {
        __builtin_trap();
    }
    out.clear();
    knob->reset(t + 1.0, out);
    line->reset(t + 1.0, out);
    held.check(out);
    held.checkNothingHeld();
    return 0;
}
