// The real kiosk, offscreen, under a notification socket as systemd would give it: READY=1
// after the first frame, watchdog keep-alives from the frame loop at half WATCHDOG_USEC,
// STOPPING=1 on the way out. And `steerseg --self-test` through the binary.
#include "support/cli_run.hpp"
#include "support/notify_socket.hpp"
#include "support/test_data.hpp"

#include <algorithm>
#include <cstdlib>
#include <fstream>
#include <gtest/gtest.h>

namespace steerseg::test {
namespace {

TEST(KioskNotify, ReadyWatchdogAndStoppingArrive) {
    const auto dir = tempDir("kiosk-notify");
    std::filesystem::current_path(dir); // the default export folder and audit log land here
    NotifySocket socket(dir);
    ::setenv("NOTIFY_SOCKET", socket.path().c_str(), 1);
    ::setenv("WATCHDOG_USEC", "400000", 1); // keep-alives every 0.2 s
    ::unsetenv("WATCHDOG_PID");
    const CliRun run = runSteerseg("kiosk --allow-root --platform offscreen --size 320x200 "
                                   "--scan builtin:sample --max-seconds 6");
    ::unsetenv("NOTIFY_SOCKET");
    ::unsetenv("WATCHDOG_USEC");
    EXPECT_EQ(run.exitCode, 1) << run.err; // --max-seconds' status
    const auto got = socket.receive();
    ASSERT_FALSE(got.empty()) << run.err;
    // The first frame shows the scan loading (on a worker); the state that follows comes as
    // a STATUS= line of its own.
    EXPECT_EQ(got.front(), "READY=1\nSTATUS=loading");
    std::string statuses;
    for (const std::string& m : got) {
        statuses += m.find("STATUS=") != std::string::npos ? m + "\n" : "";
    }
    EXPECT_NE(std::find(got.begin(), got.end(), "STATUS=inspect"), got.end())
        << "no STATUS=inspect once the scan loaded:\n"
        << statuses << run.err;
    const auto keepAlives = std::count(got.begin(), got.end(), "WATCHDOG=1");
    // 6 s at one per 0.2 s: about 30; the first frame and the exit take some of it, and never
    // more than one per 0.2 s.
    EXPECT_GE(keepAlives, 10) << run.err;
    EXPECT_LE(keepAlives, 31);
    EXPECT_EQ(got.back(), "STOPPING=1");
}

TEST(KioskNotify, NothingWithoutNotifySocket) {
    const auto dir = tempDir("kiosk-no-notify");
    std::filesystem::current_path(dir);
    NotifySocket socket(dir);
    ::unsetenv("NOTIFY_SOCKET");
    ::setenv("WATCHDOG_USEC", "400000", 1);
    const CliRun run =
        runSteerseg("kiosk --allow-root --platform offscreen --size 320x200 --max-seconds 1");
    ::unsetenv("WATCHDOG_USEC");
    EXPECT_EQ(run.exitCode, 1) << run.err;
    EXPECT_TRUE(socket.receive().empty());
}

TEST(SelfTestCli, PassesHereAndFailsOnABrokenConfig) {
    const auto dir = tempDir("self-test-cli");
    std::filesystem::current_path(dir);
    std::ofstream(dir / "site.toml")
        << "[export]\nfolder = \"" << (dir / "exports").string() << "\"\n";
    const CliRun ok = runSteerseg("--self-test --config " + (dir / "site.toml").string());
    EXPECT_EQ(ok.exitCode, 0) << ok.out << ok.err;
    EXPECT_NE(ok.out.find("  ok    gl: OpenGL ES 3."), std::string::npos) << ok.out;
    EXPECT_NE(ok.out.find("  ok    shaders: "), std::string::npos) << ok.out;
    EXPECT_NE(ok.out.find("  ok    export folder: " + (dir / "exports").string() + " writable"),
              std::string::npos)
        << ok.out;
    EXPECT_TRUE(std::filesystem::is_directory(dir / "exports"));
    EXPECT_NE(ok.out.find("self-test: passed"), std::string::npos) << ok.out;

    std::ofstream(dir / "bad.toml") << "[frame]\nbudget_ms = \"fast\"\n";
    const CliRun bad = runSteerseg("--self-test --config " + (dir / "bad.toml").string());
    EXPECT_EQ(bad.exitCode, 1) << bad.out << bad.err;
    EXPECT_NE(bad.out.find("  FAIL  config: 1 problem(s)"), std::string::npos) << bad.out;
    EXPECT_NE(bad.out.find("bad.toml:2:"), std::string::npos) << bad.out;
    EXPECT_NE(bad.out.find("self-test: FAILED"), std::string::npos) << bad.out;

    const CliRun usage = runSteerseg("--self-test --platform x11");
    EXPECT_NE(usage.exitCode, 0);
    EXPECT_EQ(std::count(usage.err.begin(), usage.err.end(), '\n') >= 1, true) << usage.err;
}

} // namespace
} // namespace steerseg::test
