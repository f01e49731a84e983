// The HID and GPIO sources, the factory and the permission messages, on a machine without
// such devices: what must hold is that each absence or refusal is one clear line.
#include "platform/input/gpio/gpio_chip.hpp"
#include "platform/input/node_access.hpp"
#include "platform/input/sources.hpp"

#include <cerrno>
#include <filesystem>
#include <fstream>
#include <grp.h>
#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>

namespace steerseg::test {
namespace {

namespace in = steerseg::platform::input;
namespace fs = std::filesystem;

bool contains(const std::string& text, const std::string& part) {
    return text.find(part) != std::string::npos;
}

in::DeviceSpec hidSpec() {
    in::DeviceSpec s;
    s.kind = in::DeviceSpec::Kind::Shuttle;
    s.name = "shuttle";
    // A vendor id no USB device carries (0xfffe is reserved), so no console attaches one.
    s.vendorId = 0xfffe;
    s.productId = 0x0001;
    return s;
}

TEST(HidSource, AbsentDeviceIsNamedByIdAndUsage) {
    std::string problem;
    EXPECT_EQ(in::openHidSource(hidSpec(), problem), nullptr);
    EXPECT_EQ(problem, "shuttle: no HID device fffe:0001 (hidraw)");

    in::DeviceSpec radial = hidSpec();
    radial.kind = in::DeviceSpec::Kind::Radial;
    radial.name = "dial";
    radial.usagePage = 0x01;
    radial.usage = 0x0e;
    EXPECT_EQ(in::openHidSource(radial, problem), nullptr);
    EXPECT_EQ(problem, "dial: no HID device fffe:0001 with usage 0001:000e (hidraw)");

    // A radial controller of any vendor, by its usage alone (no such device here).
    radial.vendorId = 0;
    radial.productId = 0;
    EXPECT_EQ(in::openHidSource(radial, problem), nullptr);
    EXPECT_EQ(problem, "dial: no HID device with usage 0001:000e (hidraw)");

    in::DeviceSpec noId;
    noId.name = "shuttle";
    EXPECT_EQ(in::openHidSource(noId, problem), nullptr);
    EXPECT_TRUE(contains(problem, "neither a vendor/product id nor a usage")) << problem;
}

TEST(HidSource, ListingReturnsWithoutCrashing) {
    for (const auto& device : in::listHidDevices()) {
        EXPECT_EQ(device.kind, "hid");
        EXPECT_FALSE(device.node.empty());
    }
}

in::DeviceSpec gpioSpec(const std::string& chip) {
    in::DeviceSpec s;
    s.kind = in::DeviceSpec::Kind::GpioInput;
    s.name = "pedal";
    s.chip = chip;
    s.line = "PEDAL";
    return s;
}

TEST(GpioSource, MissingChipIsNamed) {
    if (fs::exists("/dev/gpiochip99")) {
        GTEST_SKIP() << "a /dev/gpiochip99 exists here";
    }
    std::string problem;
    EXPECT_EQ(in::openGpioSource(gpioSpec("gpiochip99"), problem), nullptr);
    EXPECT_EQ(problem, "pedal: /dev/gpiochip99: open failed: No such file or directory");
    EXPECT_EQ(in::openGpioSource(gpioSpec("99"), problem), nullptr);
    EXPECT_TRUE(contains(problem, "/dev/gpiochip99: open failed")) << problem;
    EXPECT_EQ(in::openGpioSource(gpioSpec("no-such-label"), problem), nullptr);
    EXPECT_EQ(problem, "pedal: gpio chip 'no-such-label': no chip with that label in /dev");

    in::DeviceSpec led = gpioSpec("gpiochip99");
    led.kind = in::DeviceSpec::Kind::GpioLed;
    led.name = "status_led";
    EXPECT_EQ(in::openGpioSource(led, problem), nullptr);
    EXPECT_TRUE(contains(problem, "status_led: /dev/gpiochip99")) << problem;
}

TEST(GpioSource, ARegularFileIsNoChipAndSpecsAreChecked) {
    const fs::path file = fs::temp_directory_path() / ("steerseg_gpio_" + std::to_string(getpid()));
    std::ofstream(file) << "not a chip";
    std::string problem;
    EXPECT_EQ(in::openGpioSource(gpioSpec(file.string()), problem), nullptr);
    EXPECT_TRUE(contains(problem, "pedal: " + file.string() + ": open failed")) << problem;
    fs::remove(file);

    in::DeviceSpec noLine = gpioSpec("gpiochip0");
    noLine.line.clear();
    EXPECT_EQ(in::openGpioSource(noLine, problem), nullptr);
    EXPECT_EQ(problem, "pedal: no GPIO line given");
    in::DeviceSpec noChip = gpioSpec("");
    EXPECT_EQ(in::openGpioSource(noChip, problem), nullptr);
    EXPECT_EQ(problem, "pedal: gpio: no chip given");
}

TEST(GpioSource, ListingOfAnEmptyDirectoryIsEmpty) {
    const fs::path dir =
        fs::temp_directory_path() / ("steerseg_gpiodir_" + std::to_string(getpid()));
    fs::create_directories(dir);
    EXPECT_TRUE(in::gpio::listGpioChipsV1(dir.string()).empty());
    fs::remove_all(dir);
    EXPECT_TRUE(in::gpio::listGpioChipsV1("/nonexistent-steerseg").empty());
    for (const auto& chip : in::listGpioChips()) {
        EXPECT_EQ(chip.kind, "gpiochip");
    }
}

TEST(SourceFactory, DispatchesByKind) {
    std::string problem;
    EXPECT_EQ(in::openSource(hidSpec(), problem), nullptr);
    EXPECT_TRUE(contains(problem, "no HID device")) << problem;
    in::DeviceSpec powermate;
    powermate.kind = in::DeviceSpec::Kind::PowerMate;
    powermate.name = "powermate";
    powermate.path = "/nonexistent-steerseg/event0";
    EXPECT_EQ(in::openSource(powermate, problem), nullptr);
    EXPECT_TRUE(contains(problem, "powermate: /nonexistent-steerseg/event0: open failed"))
        << problem;
    EXPECT_EQ(in::openSource(gpioSpec("no-such-label"), problem), nullptr);
    EXPECT_TRUE(contains(problem, "gpio chip 'no-such-label'")) << problem;
}

TEST(NodeAccess, PermissionMessagesNameWhatIsMissing) {
    const std::string node = "/nonexistent-steerseg/hidraw0";
    EXPECT_EQ(in::nodeOpenProblem(node, "open", ENOENT),
              node + ": open failed: No such file or directory");
    const std::string noGroup = in::nodeOpenProblem(node, "open", EACCES, "steerseg_no_such_group");
    EXPECT_TRUE(contains(noGroup, node + ": open failed: Permission denied")) << noGroup;
    EXPECT_TRUE(contains(noGroup, "group 'steerseg_no_such_group' does not exist")) << noGroup;

    // A node of another group than the wanted one: the udev rule did not apply.
    const fs::path file = fs::temp_directory_path() / ("steerseg_node_" + std::to_string(getpid()));
    std::ofstream(file) << "x";
    struct stat st {};
    ASSERT_EQ(stat(file.c_str(), &st), 0);
    const group* own = getgrgid(st.st_gid);
    const group* other = nullptr;
    for (const char* name : {"root", "daemon", "bin", "sys", "adm", "nogroup", "users"}) {
        const group* g = getgrnam(name);
        if (g != nullptr && g->gr_gid != st.st_gid) {
            other = g;
            break;
        }
    }
    if (own == nullptr || other == nullptr) {
        fs::remove(file);
        GTEST_SKIP() << "no second group to test with";
    }
    const std::string otherName = other->gr_name;
    const std::string ownName = own->gr_name;
    const std::string rule = in::nodeOpenProblem(file.string(), "open", EACCES, otherName);
    EXPECT_TRUE(contains(rule, "belongs to group '" + ownName + "', not '" + otherName + "'"))
        << rule;
    EXPECT_TRUE(contains(rule, "70-steerseg.rules")) << rule;
    fs::remove(file);
}

} // namespace
} // namespace steerseg::test
