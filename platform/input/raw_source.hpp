#pragma once

// One opened input device read without blocking: it yields raw records for the decoders and
// takes the indicator state for its LED where it has one. An unplugged device reports Gone
// once and is then closed by its owner; the hotplug monitor brings it back.
#include "platform/input/raw_record.hpp"

#include <string>
#include <vector>

namespace steerseg::platform::input {

// The LED's meaning follows the workflow: steady while evolving, pulsing while paused, off
// when idle.
enum class Indicator { Off, Steady, Pulsing };

class RawSource {
  public:
    enum class ReadStatus {
        Ok,     // zero or more records appended
        Gone,   // the device was unplugged (ENODEV and the like); `problem` says which
        Failed, // an error that may pass (EIO, a short read); `problem` says what
    };
    virtual ~RawSource() = default;
    [[nodiscard]] virtual const std::string& name() const = 0;
    // The file descriptor to poll() for input, or -1 where the source must be read each frame.
    [[nodiscard]] virtual int fd() const = 0;
    // Appends what is pending (at most `maxRecords`, so a flood cannot stall a frame) and
    // returns at once; `now` stamps the records.
    virtual ReadStatus read(double now, std::size_t maxRecords, std::vector<RawRecord>& out,
                            std::string& problem) = 0;
    virtual void setIndicator(Indicator) {}
};

} // namespace steerseg::platform::input
