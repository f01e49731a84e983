#pragma once

#include <string>

namespace steerseg::test {

struct CliRun {
    int exitCode = -1; // -1 if the process did not exit normally (a crash)
    std::string out;
    std::string err;
};

// Runs the steerseg binary under test with `arguments` (shell words; test paths hold no spaces)
// and captures its exit code, stdout and stderr.
CliRun runSteerseg(const std::string& arguments);

} // namespace steerseg::test
