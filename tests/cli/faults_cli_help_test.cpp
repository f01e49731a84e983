// The real binary's answers to what an operator types: every command's --help is its usage on
// stdout and status 0; a script error is its line and reason alone, and leaves no --frames
// folder behind; --self-test takes the --allow-root the kiosk requires as root.
#include "support/cli_run.hpp"
#include "support/test_data.hpp"

#include <algorithm>
#include <fstream>
#include <gtest/gtest.h>

namespace steerseg::test {
namespace {

long lineCount(const std::string& text) {
    return std::count(text.begin(), text.end(), '\n');
}

TEST(FaultsCliHelp, EveryCommandsHelpIsItsUsageAndZero) {
    for (const std::string command :
         {"info", "gpu-info", "render", "segment", "export", "kiosk", "self-test", "--self-test",
          "input-monitor", "send", "listen"}) {
        for (const std::string flag : {"--help", "-h"}) {
            SCOPED_TRACE(command + " " + flag);
            const CliRun r = runSteerseg(command + " " + flag);
            EXPECT_EQ(r.exitCode, 0) << r.err;
            EXPECT_EQ(r.out.rfind("usage: steerseg ", 0), 0u) << r.out;
            EXPECT_EQ(lineCount(r.out), 1) << r.out;
            EXPECT_EQ(r.err, "");
        }
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
