#pragma once

// Turns one device's raw records into control events. Decoders are pure (no I/O, no clock of
// their own): the same object decodes a live device and a recording. Nothing a device sends
// may crash one or make it allocate without bound: a malformed record is dropped and named
// in problem().
#include "platform/input/control_event.hpp"
#include "platform/input/raw_record.hpp"

#include <string>
#include <vector>

namespace steerseg::platform::input {

class Decoder {
  public:
    virtual ~Decoder() = default;
    // Decodes one record of this decoder's device (records of other kinds are problems).
    virtual void feed(const RawRecord& record, std::vector<ControlEvent>& out) = 0;
    // Lets time pass without input: a debounced line settles, a held control repeats.
    virtual void tick(double now, std::vector<ControlEvent>& out) = 0;
    // The device went away: held buttons are released and rings return to rest, so nothing
    // stays pressed or turning after an unplug.
    virtual void reset(double now, std::vector<ControlEvent>& out) = 0;
    // The problems since the last call, one line each ("shuttle: report of 3 bytes, expected
    // 5"), for the rate-limited log; empty when there were none.
    virtual std::vector<std::string> takeProblems() = 0;
};

} // namespace steerseg::platform::input
