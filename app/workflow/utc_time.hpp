#pragma once

// UTC time stamps for the audit log and export file names (the console's clock may be set to
// any zone; records and names must not depend on it).
#include <chrono>
#include <string>

namespace steerseg::workflow {

std::string isoUtc(std::chrono::system_clock::time_point t);     // 2026-11-23T13:01:40.123Z
std::string compactUtc(std::chrono::system_clock::time_point t); // 20261123-130140

} // namespace steerseg::workflow
