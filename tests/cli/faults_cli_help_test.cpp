// The real binary's answers to what an operator types: every command's --help is its usage on
// stdout and status 0; a script error is its line and reason alone, and leaves no --frames
// folder behind; --self-test takes the --allow-root the kiosk requires as root.
#include "support/cli_run.hpp"
#include "support/test_data.hpp"

#include <algorithm>
#include <fstream>
#include <gtest/gtest.h>
#include <string>
#include <vector>

namespace steerseg::test {
namespace {

long lineCount(const std::string& text) {
    return std::count(text.begin(), text.end(), '\n');
}

TEST(FaultsCliHelp, EveryCommandsHelpIsItsUsageAndZero) {
    // Every command with --help; -h is the same word to the one check of all commands
    // (asksForHelp), so two commands with it, one after another option, say enough for it (a
    // run of the binary costs about half a second, more under the sanitizers).
    std::vector<std::string> asks;
    for (const std::string command :
         {"info", "gpu-info", "render", "segment", "export", "kiosk", "self-test", "--self-test",
          "input-monitor", "send", "listen"}) {
        asks.push_back(command + " --help");
    }
    asks.emplace_back("render -h");
    asks.emplace_back("segment --input builtin:sample -h");
    for (const std::string& ask : asks) {
        SCOPED_TRACE(ask);
        const CliRun r = runSteerseg(ask);
        EXPECT_EQ(r.exitCode, 0) << r.err;
        EXPECT_EQ(r.out.rfind("usage: steerseg ", 0), 0u) << r.out;
        EXPECT_EQ(lineCount(r.out), 1) << r.out;
        EXPECT_EQ(r.err, "");
    }
}

TEST(FaultsCliHelp, AScriptErrorIsItsLineAloneAndMakesNoFramesFolder) {
    const auto dir = tempDir("faults-script-error");
    std::ofstream(dir / "bad.session") << "load builtin:sample\nfly to the moon\n";
    const auto frames = dir / "frames";
    const CliRun r =
        runSteerseg("kiosk --allow-root --platform offscreen --size 320x200 --script " +
                    (dir / "bad.session").string() + " --frames " + frames.string());
    EXPECT_EQ(r.exitCode, 2) << r.err;
    EXPECT_EQ(lineCount(r.err), 1) << r.err;
    EXPECT_NE(r.err.find("bad.session:2"), std::string::npos) << r.err;
    EXPECT_EQ(r.err.find("usage:"), std::string::npos) << r.err;
    EXPECT_FALSE(std::filesystem::exists(frames));
}

TEST(FaultsCliHelp, SelfTestTakesAllowRoot) {
    const CliRun plain = runSteerseg("--self-test");
    const CliRun root = runSteerseg("--self-test --allow-root");
    EXPECT_NE(root.exitCode, 2) << root.err;
    EXPECT_EQ(root.exitCode, plain.exitCode) << root.err;
    EXPECT_EQ(root.err.find("allow-root"), std::string::npos) << root.err;
}

} // namespace
} // namespace steerseg::test
