// The HID decoders on arbitrary bytes: the first byte chooses the shuttle or the radial
// decoder, the next two give the length of a report descriptor, and the rest is split into
// reports, each prefixed by its length byte (0xFF instead: an unplug). Decoding must never crash,
// problems stay bounded, and presses and releases stay paired (fuzz_input_checks.hpp).
#include "fuzz_input_checks.hpp"
#include "platform/input/decoders.hpp"
#include "platform/input/hid/report_descriptor.hpp"

#include <algorithm>
#include <cstdint>
#include <string>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    using namespace steerseg::platform::input;
    if (size < 3) {
        return 0;
    }
    DeviceSpec spec;
    spec.name = "knob";
    spec.kind = (data[0] & 1U) != 0 ? DeviceSpec::Kind::Radial : DeviceSpec::Kind::Shuttle;
    std::size_t descriptorBytes = data[1] | (std::size_t{data[2]} << 8);
    std::size_t at = 3;
    if (descriptorBytes > size - at) {
        descriptorBytes = size - at;
    }
    auto decoder = makeDecoder(spec);
    steerseg::fuzz::HeldControls held;
    std::vector<ControlEvent> out;
    RawRecord record;
    record.device = spec.name;
    record.kind = RawRecord::Kind::HidDescriptor;
    record.bytes.assign(data + at, data + at + descriptorBytes);
    std::string problem;
    (void)hid::parseReportDescriptor(record.bytes, problem);
    decoder->feed(record, out);
    at += descriptorBytes;
    double t = 0.0;
    while (at < size) {
        const std::uint8_t prefix = data[at++];
        // 0xFF: the device is unplugged (and keeps its descriptor for the replug)
        const std::size_t length = prefix == 0xFF ? 0 : std::min<std::size_t>(prefix, size - at);
        record.kind = prefix == 0xFF ? RawRecord::Kind::Unplugged : RawRecord::Kind::HidReport;
        record.time = (t += 0.001);
        record.bytes.assign(data + at, data + at + length);
        decoder->feed(record, out);
        at += length;
    }
    held.check(out);
    if (decoder->takeProblems().size() > 33) {
        __builtin_trap(); // the problem log must stay bounded
    }
    out.clear();
    decoder->reset(t, out);
    held.check(out);
    held.checkNothingHeld();
    return 0;
}
