#pragma once

// hidapi's process-wide state: hid_init before the first call, hid_exit when the process ends.
#include <string>

namespace steerseg::platform::input {

// True once hidapi is initialised; `problem` says why not otherwise.
bool ensureHidLibrary(std::string& problem);

} // namespace steerseg::platform::input
