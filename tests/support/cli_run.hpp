#pragma once

#include <filesystem>
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

// Any shell command (another program: dciodvfy, dsrdump, python3), its stdout and stderr
// together.
struct ShellRun {
    int status = -1; // -1 if the process did not exit normally
    std::string output;
};
ShellRun runShell(const std::string& command);
// A path as one shell word (test paths hold no quote).
std::string shellQuoted(const std::filesystem::path& path);

// dciodvfy (dicom3tools) on a DICOM file: it names `iod` on a line of its own (proof that it ran
// and knew the object), and no line is an error; warnings are printed in the test's output.
void expectDciodvfyValid(const std::filesystem::path& file, const std::string& iod);

} // namespace steerseg::test
