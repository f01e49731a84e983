#pragma once

// The input hub's backends: the live devices of platform/input (sources, decoders, the hotplug
// monitor), or decoders alone for a replay.
#include "input/input_hub.hpp"

#include <iosfwd>
#include <string>

namespace steerseg::input {

// openSource, makeDecoder and a HotplugMonitor (udev, else a rescan of /dev) whose notice, if
// any, goes to `log` once after `prefix`.
InputHub::Backend liveInputBackend(std::ostream& log, const std::string& prefix);
// makeDecoder only: nothing is opened.
InputHub::Backend replayInputBackend();

} // namespace steerseg::input
