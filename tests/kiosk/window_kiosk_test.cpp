// The kiosk's window backend for real (issue 10, docs/kiosk.md): CTest runs this under xvfb-run
// with a screen the size of the kiosk's window. One session (tests/scenarios/window_check.session)
// is replayed twice: offscreen, giving frame A, and in a window on the X server. The X screen's
// picture when the window run reaches its `frame` step must match frame A within the golden
// tolerance; then a click and a key injected into the X server with xdotool must reach the
// workflow as the script's own tap and key at the same pixel do in the offscreen run.
#include "core/rgba_image.hpp"
#include "exports/image_file.hpp"
#include "kiosk/child_process.hpp"
#include "render/golden_compare.hpp"
#include "support/test_data.hpp"
#include "support/write_faults.hpp"
#include "support/x11_probe.hpp"
#include "ui/layout.hpp"

#include <chrono>
#include <cstdint>
#include <cstdlib>
#include <fstream>
#include <gtest/gtest.h>
#include <iostream>
#include <nlohmann/json.hpp>
#include <optional>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

namespace steerseg::test {
namespace {

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

// The X screen (tests/kiosk/CMakeLists.txt gives xvfb-run the same size): the window fills it
// from 0,0, so a screenshot of the screen is the window's picture.
constexpr int kWidth = 640;
constexpr int kHeight = 400;
// Both runs give the layout the same DPI (a window would otherwise ask the X server).
constexpr double kDpi = 96.0;
constexpr auto kRunTimeout = std::chrono::seconds(150);
constexpr auto kShowTimeout = std::chrono::seconds(15);

// What both runs do after window_check.session's frame: wait for a tap on the first slice view
// (a second seed) and for the space key (bound to toggle_run in config/steerseg.toml: the run
// resumes), then stop. The offscreen run gets the tap and key from the script itself; the
// window run from the X server.
constexpr const char* kAfterInput = "wait until seeds >= 2 timeout 60\n"
                                    "wait state evolving timeout 60\n"
                                    "pause\n"
                                    "wait state paused\n"
                                    "expect seeds == 2\n";

// Why the test cannot run here (no X server from xvfb-run, no xdotool), or nullopt.
std::optional<std::string> missingTools() {
    if (const char* missing = std::getenv("STEERSEG_XVFB_MISSING");
        missing != nullptr && std::string(missing) == "1") {
        return "xvfb-run was not found when the build was configured";
    }
    if (std::getenv("DISPLAY") == nullptr) {
        return "no X display (CTest runs this test under xvfb-run)";
    }
    if (std::system("command -v xdotool >/dev/null 2>&1") != 0) {
        return "xdotool not found";
    }
    return std::nullopt;
}

// A config for one run: the same frame for both (fixed iterations per frame, so `wait
// iterations` stops both at the same count), its own audit log and autosave folder (the first
// run ends with unexported work: a shared folder would put a resume prompt over the second's).
fs::path writeConfig(const fs::path& dir, const std::string& name) {
    const fs::path path = dir / (name + ".toml");
    std::ofstream(path) << "[display]\n"
                        << "dpi = " << kDpi << "\n"
                        << "[frame]\n"
                        << "min_iterations = 8\n"
                        << "max_iterations = 8\n"
                        << "[audit]\n"
                        << "path = \"" << (dir / (name + "-audit.jsonl")).string() << "\"\n"
                        << "[export]\n"
                        << "folder = \"" << (dir / "export").string() << "\"\n"
                        << "[autosave]\n"
                        << "folder = \"" << (dir / (name + "-autosave")).string() << "\"\n";
    return path;
}

fs::path writeSession(const fs::path& dir, const std::string& name, const std::string& tail) {
    const fs::path path = dir / (name + ".session");
    std::ofstream(path) << readText(STEERSEG_WINDOW_SESSION) << tail;
    return path;
}

std::vector<std::string> kioskArgs(const std::string& platform, const fs::path& dir,
                                   const std::string& name) {
    return {steersegBinary().string(),
            "kiosk",
            "--platform",
            platform,
            "--script",
            (dir / (name + ".session")).string(),
            "--frames",
            (dir / name).string(),
            "--size",
            std::to_string(kWidth) + "x" + std::to_string(kHeight),
            "--config",
            (dir / (name + ".toml")).string(),
            "--allow-root"};
}

std::string describeRun(const fs::path& dir, const std::string& name) {
    return "\n--- " + name + " stdout:\n" + readText(dir / (name + ".out")) + "--- " + name +
           " stderr:\n" + readText(dir / (name + ".err"));
}

// The image at `path` once the kiosk has written it whole: its size stays put between two
// polls, and OpenImageIO (which refuses a partial PNG) reads it.
std::optional<RgbaImage> readWhenWritten(const fs::path& path, ChildProcess& kiosk,
                                         Clock::time_point deadline) {
    std::uintmax_t lastSize = 0;
    while (Clock::now() < deadline) {
        std::error_code ec;
        const std::uintmax_t size = fs::file_size(path, ec);
        const bool steady = !ec && size > 0 && size == lastSize;
        lastSize = ec ? 0 : size;
        if (steady) {
            try {
                return exports::readImage(path); // a wrong size is compareImages' to name
            } catch (const std::exception&) {
                // still being written
            }
        }
        if (!kiosk.running() && !fs::exists(path)) {
            return std::nullopt;
        }
        std::this_thread::sleep_for(std::chrono::milliseconds(50));
    }
    return std::nullopt;
}

RgbaImage screenshot(const X11Probe& x) {
    return {kWidth, kHeight, x.capture(x.rootWindow(), kWidth, kHeight)};
}

// The X screen once it shows `expected` exactly (the frame the kiosk wrote is the one it
// presented, but the X server may show it a moment later), or its last picture at the deadline.
RgbaImage screenshotShowing(const X11Probe& x, const RgbaImage& expected) {
    RgbaImage shot = screenshot(x);
    const auto deadline = Clock::now() + kShowTimeout;
    while (shot.pixels != expected.pixels && Clock::now() < deadline) {
        std::this_thread::sleep_for(std::chrono::milliseconds(50));
        shot = screenshot(x);
    }
    return shot;
}

void xdotool(const std::string& arguments) {
    const std::string command = "xdotool " + arguments;
    ASSERT_EQ(std::system(command.c_str()), 0) << command << " failed";
}

struct AuditEntries {
    std::vector<nlohmann::json> seeds;   // accepted add_seed actions, in order
    std::vector<nlohmann::json> toggles; // accepted toggle_run actions
};

AuditEntries readAudit(const fs::path& path) {
    AuditEntries a;
    std::istringstream lines(readText(path));
    for (std::string line; std::getline(lines, line);) {
        const nlohmann::json record = nlohmann::json::parse(line, nullptr, false);
        if (record.is_discarded() || record.value("event", "") != "action" ||
            !record.value("accepted", false)) {
            continue;
        }
        const std::string action = record.value("action", "");
        if (action == "add_seed") {
            a.seeds.push_back(record);
        } else if (action == "toggle_run") {
            a.toggles.push_back(record);
        }
    }
    return a;
}

TEST(KioskWindow, XScreenShowsTheOffscreenFrameAndXInputReachesTheWorkflow) {
    if (const auto missing = missingTools()) {
        if (dataRequired()) {
            FAIL() << *missing << " (STEERSEG_REQUIRE_DATA=1: tools/install-deps.sh installs "
                   << "xvfb and xdotool)";
        }
        GTEST_SKIP() << *missing << " (tools/install-deps.sh installs xvfb and xdotool)";
    }
    X11Probe x;
    ASSERT_TRUE(x.connected()) << "cannot connect to the X display " << std::getenv("DISPLAY");
    const fs::path dir = tempDir("kiosk-window");

    // The centre of the first slice view: a tap there seeds the voxel it shows.
    const ui::Layout layout = ui::computeLayout(kWidth, kHeight, kDpi);
    const int tapX = layout.slice1.x + layout.slice1.w / 2;
    const int tapY = layout.slice1.y + layout.slice1.h / 2;
    const std::string tap = std::to_string(tapX) + " " + std::to_string(tapY);

    // Offscreen: frame A, and the script's own tap and key.
    writeConfig(dir, "offscreen");
    writeSession(dir, "offscreen", "tap " + tap + "\nkey space\n" + kAfterInput);
    {
        ChildProcess kiosk(kioskArgs("offscreen", dir, "offscreen"), dir / "offscreen.out",
                           dir / "offscreen.err");
        const std::optional<int> rc = kiosk.wait(kRunTimeout);
        ASSERT_TRUE(rc.has_value()) << "the offscreen run did not end within "
                                    << kRunTimeout.count() << " s" << describeRun(dir, "offscreen");
        ASSERT_EQ(*rc, 0) << "the offscreen run failed" << describeRun(dir, "offscreen");
    }
    const fs::path frameA = dir / "offscreen" / "window_check.png";
    const RgbaImage offscreen = exports::readImage(frameA);
    ASSERT_EQ(offscreen.width, kWidth);
    ASSERT_EQ(offscreen.height, kHeight);

    // In a window: the pointer parked on the 3D view's corner, away from the panel's buttons
    // and the slices, so nothing on the screen reacts to it.
    xdotool("mousemove 2 " + std::to_string(kHeight - 3));
    writeConfig(dir, "window");
    writeSession(dir, "window", kAfterInput);
    ChildProcess kiosk(kioskArgs("window", dir, "window"), dir / "window.out", dir / "window.err");
    const fs::path frameB = dir / "window" / "window_check.png";
    const std::optional<RgbaImage> drawn =
        readWhenWritten(frameB, kiosk, Clock::now() + kRunTimeout);
    ASSERT_TRUE(drawn.has_value())
        << "the window run never reached its frame step"
        << (kiosk.running() ? " (still running)" : "") << describeRun(dir, "window");
    const RgbaImage shown = screenshotShowing(x, *drawn);
    ASSERT_EQ(shown.pixels.size(), offscreen.pixels.size())
        << "cannot read the X screen" << describeRun(dir, "window");
    const GoldenResult match = compareImages("X screen vs offscreen frame", offscreen, shown);
    if (!match.ok) {
        const fs::path shot = dir / "x-screen.png";
        const fs::path diff = dir / "x-screen.diff.png";
        exports::writeImage(shot, shown);
        exports::writeImage(diff, match.diff);
        ADD_FAILURE() << match.message << " the X screen " << shot << " ("
                      << (shown.pixels == drawn->pixels ? "equal to" : "unlike")
                      << " the window run's own frame " << frameB << "), the offscreen frame "
                      << frameA << ", diff " << diff;
    }

    // Input through the X server: a click on the first slice view, then the space key (Xvfb
    // has no window manager: keys go to the window under the pointer).
    xdotool("mousemove " + tap + " click 1");
    xdotool("key space");
    const std::optional<int> rc = kiosk.wait(kRunTimeout);
    ASSERT_TRUE(rc.has_value()) << "the window run did not end within " << kRunTimeout.count()
                                << " s after the input" << describeRun(dir, "window");
    ASSERT_EQ(*rc, 0) << "the window run failed: the click or the key did not reach the workflow?"
                      << describeRun(dir, "window");

    // The audit logs: the click seeded the voxel the script's tap at the same pixel seeded, and
    // the key resumed the run as the script's key did.
    const AuditEntries byScript = readAudit(dir / "offscreen-audit.jsonl");
    const AuditEntries byX = readAudit(dir / "window-audit.jsonl");
    ASSERT_EQ(byScript.seeds.size(), 2U) << readText(dir / "offscreen-audit.jsonl");
    ASSERT_EQ(byX.seeds.size(), 2U) << "the click on the slice view added no seed\n"
                                    << readText(dir / "window-audit.jsonl");
    EXPECT_EQ(byX.seeds[1]["values"]["voxel"], byScript.seeds[1]["values"]["voxel"])
        << "the click seeded another voxel than the script's tap at (" << tap << ")";
    EXPECT_EQ(byX.seeds[1]["state"], "paused");
    ASSERT_EQ(byScript.toggles.size(), 1U) << readText(dir / "offscreen-audit.jsonl");
    ASSERT_EQ(byX.toggles.size(), 1U) << "the space key did not toggle the run\n"
                                      << readText(dir / "window-audit.jsonl");
    EXPECT_EQ(byX.toggles[0]["state"], "paused");

    if (!HasFailure()) {
        fs::remove_all(dir);
    } else {
        std::cout << "kept " << dir << " for inspection\n";
    }
}

} // namespace
} // namespace steerseg::test
