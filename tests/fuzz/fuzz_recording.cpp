// The recording file on arbitrary bytes: parsing never crashes and stays bounded, and every
// record it keeps formats to a line that parses back to the same line.
#include "platform/input/recording.hpp"

#include <cstdint>
#include <sstream>
#include <string>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    using namespace steerseg::platform::input;
    std::istringstream in(std::string(reinterpret_cast<const char*>(data), size));
    const Recording rec = parseRecording(in, "fuzz", 1000);
    if (rec.records.size() > 1000 || rec.problems.size() > 101) {
        __builtin_trap();
    }
    for (const RawRecord& r : rec.records) {
        const std::string line = formatRecordLine(r);
        std::string problem;
        const auto back = parseRecordLine(line, problem);
        if (!back || formatRecordLine(*back) != line) {
            __builtin_trap(); // a kept record must survive its own line
        }
    }
    return 0;
}
