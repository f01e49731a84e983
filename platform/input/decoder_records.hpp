#pragma once

// What every decoder does with a record that is not its device's data: an unplug releases what
// was held (reset), a replug needs nothing (the next data sets the reference again), and a
// record of another kind is named as a problem and dropped.
#include "platform/input/decoder.hpp"
#include "platform/input/problem_log.hpp"

#include <string>
#include <string_view>
#include <vector>

namespace steerseg::platform::input {

// `kind` completes "not ... record": "a HID", "an evdev", "a GPIO".
inline void feedOtherRecord(Decoder& decoder, const RawRecord& record,
                            std::vector<ControlEvent>& out, ProblemLog& problems,
                            const std::string& name, std::string_view kind) {
    switch (record.kind) {
    case RawRecord::Kind::Unplugged:
        decoder.reset(record.time, out);
        return;
    case RawRecord::Kind::Plugged:
        return;
    default:
        problems.add(name + ": not " + std::string(kind) + " record (ignored)");
        return;
    }
}

} // namespace steerseg::platform::input
