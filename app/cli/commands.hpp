#pragma once

#include <span>
#include <string>

namespace steerseg::cli {

// Each command takes the words after its name and returns the process exit status:
// 0 success, 1 runtime failure (bad scan, GPU refused), 2 usage error.
int runGpuInfo(std::span<const std::string> args);
int runInfo(std::span<const std::string> args);
int runRender(std::span<const std::string> args);
int runSegment(std::span<const std::string> args);

} // namespace steerseg::cli
