#pragma once

#include <exception>
#include <span>
#include <string>

namespace steerseg::cli {

// The process exit status. A command returns kExitOk; every failure is an exception that main()
// maps to one of the others by its type (exitStatusOf), prints on one line and, for kExitUsage,
// follows with the command's usage. `steerseg --help` lists them; README's "Exit status" too.
enum ExitStatus : int {
    kExitOk = 0,
    kExitFailure = 1, // the scan (or --mask) cannot be read (scan::ScanError), or another failure
    kExitUsage = 2,   // a bad or missing option (UsageError), or --seed/--erase outside the scan
    kExitGpu = 3,     // no GPU context (platform::GpuContextError) or a GL error (gpu::GlError)
    kExitWrite = 4,   // an output cannot be written (files::WriteError)
};

// The exit status for an exception thrown by a command.
ExitStatus exitStatusOf(const std::exception& e);

// One line per status, for --help.
const char* exitStatusHelp();

// Each command takes the words after its name and returns kExitOk.
int runExport(std::span<const std::string> args);
int runGpuInfo(std::span<const std::string> args);
int runInfo(std::span<const std::string> args);
int runInputMonitor(std::span<const std::string> args);
int runKiosk(std::span<const std::string> args);
int runListen(std::span<const std::string> args);
int runMeasure(std::span<const std::string> args);
int runQuery(std::span<const std::string> args);
int runRender(std::span<const std::string> args);
int runRetrieve(std::span<const std::string> args);
int runSegment(std::span<const std::string> args);
int runSelfTest(std::span<const std::string> args);
int runSend(std::span<const std::string> args);

} // namespace steerseg::cli
