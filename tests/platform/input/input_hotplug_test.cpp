// The hotplug monitor's rescan, the path it takes where udev is not running: nodes appearing
// and vanishing under a device directory are reported once each.
#include "platform/input/hotplug_monitor.hpp"

#include <filesystem>
#include <fstream>
#include <gtest/gtest.h>
#include <unistd.h>

namespace steerseg::test {
namespace {

namespace in = steerseg::platform::input;
namespace fs = std::filesystem;
using Action = in::HotplugChange::Action;

class HotplugRescan : public ::testing::Test {
  protected:
    void SetUp() override {
        dir_ = fs::temp_directory_path() / ("steerseg_hotplug_" + std::to_string(::getpid()));
        fs::remove_all(dir_);
        fs::create_directories(dir_ / "input");
    }
    void TearDown() override { fs::remove_all(dir_); }
    void touch(const std::string& rel) { std::ofstream(dir_ / rel) << ""; }
    fs::path dir_;
};

TEST_F(HotplugRescan, ReportsNodesThatComeAndGo) {
    touch("hidraw0");
    touch("input/event3");
    touch("input/mouse0"); // not an event node
    touch("tty0");
    in::HotplugOptions options;
    options.useUdev = false;
    options.devDir = dir_.string();
    options.rescanSeconds = 2.0;
    in::HotplugMonitor monitor(options);
    EXPECT_FALSE(monitor.usingUdev());
    EXPECT_EQ(monitor.fd(), -1);
    const std::string notice = monitor.takeNotice();
    EXPECT_NE(notice.find("rescanning " + dir_.string() + " every 2 s"), std::string::npos)
        << notice;
    EXPECT_TRUE(monitor.takeNotice().empty()) << "the notice is said once";

    // The first scan reports what is there.
    std::vector<in::HotplugChange> changes;
    monitor.poll(10.0, changes);
    ASSERT_EQ(changes.size(), 2U);
    EXPECT_EQ(changes[0].action, Action::Added);
    EXPECT_EQ(changes[0].subsystem, "hidraw");
    EXPECT_EQ(changes[0].devnode, (dir_ / "hidraw0").string());
    EXPECT_EQ(changes[1].subsystem, "input");
    EXPECT_EQ(changes[1].devnode, (dir_ / "input/event3").string());

    fs::remove(dir_ / "hidraw0");
    touch("gpiochip0");
    changes.clear();
    monitor.poll(11.0, changes);
    EXPECT_TRUE(changes.empty()) << "rescans wait for their period";
    monitor.poll(12.0, changes);
    ASSERT_EQ(changes.size(), 2U);
    EXPECT_EQ(changes[0].action, Action::Removed);
    EXPECT_EQ(changes[0].devnode, (dir_ / "hidraw0").string());
    EXPECT_EQ(changes[1].action, Action::Added);
    EXPECT_EQ(changes[1].subsystem, "gpio");

    changes.clear();
    monitor.poll(20.0, changes);
    EXPECT_TRUE(changes.empty()) << "nothing changed";
}

TEST_F(HotplugRescan, AMissingDirectoryIsEmptyNotAnError) {
    in::HotplugOptions options;
    options.useUdev = false;
    options.devDir = (dir_ / "absent").string();
    in::HotplugMonitor monitor(options);
    std::vector<in::HotplugChange> changes;
    monitor.poll(0.0, changes);
    EXPECT_TRUE(changes.empty());
}

TEST(Hotplug, WithoutUdevRunningFallsBackAndSaysWhy) {
    if (fs::exists("/run/udev/control")) {
        GTEST_SKIP() << "udev runs here";
    }
    in::HotplugMonitor monitor;
    EXPECT_FALSE(monitor.usingUdev());
    EXPECT_NE(monitor.takeNotice().find("udev is not running"), std::string::npos);
}

} // namespace
} // namespace steerseg::test
