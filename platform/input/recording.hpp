#pragma once

// The recording file: raw records as text, one per line, so a field engineer can read it, cut
// it and paste lines into a session script (which embeds the same lines). `steerseg
// input-monitor --record FILE` writes it; replaying feeds the lines to the same decoders.
//
//   # steerseg input recording 1
//   0.000000 shuttle hid-descriptor 05010908a101...   (hex, any length up to 4096 bytes)
//   0.016000 shuttle hid 0403ff0000                     (one report, hex)
//   0.020000 powermate evdev 2 7 1                      (type code value, decimal)
//   0.030000 pedal gpio 1                               (1 = active, 0 = released)
//   0.500000 shuttle unplug
//   0.900000 shuttle plug
//
// Times are seconds from the start, non-decreasing; device names are control names (a-z,
// 0-9, _). Blank lines and lines starting with '#' are skipped.
#include "platform/input/raw_record.hpp"

#include <iosfwd>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace steerseg::platform::input {

// One line -> one record; nothing and a one-line `problem` for a malformed line (a blank or
// comment line gives nothing and no problem).
std::optional<RawRecord> parseRecordLine(std::string_view line, std::string& problem);
// The line for a record, without the newline; parseRecordLine(formatRecordLine(r)) == r.
std::string formatRecordLine(const RawRecord& record);

struct Recording {
    std::vector<RawRecord> records;
    // "FILE:LINE: problem" for each line that was skipped; a recording with problems still
    // replays its good lines.
    std::vector<std::string> problems;
};
// Reads a whole recording; a missing or unreadable file is one problem, not a throw. At most
// `maxRecords` are kept (a problem says the rest were dropped).
Recording readRecording(const std::string& path, std::size_t maxRecords = 10'000'000);
Recording parseRecording(std::istream& in, const std::string& name,
                         std::size_t maxRecords = 10'000'000);

} // namespace steerseg::platform::input
