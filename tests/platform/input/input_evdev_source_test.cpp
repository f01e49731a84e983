// The evdev source on what it reads in tests and replays: FIFOs and regular files holding
// struct input_event records (the ioctls a real node answers fail there with ENOTTY).
#include "platform/input/evdev/powermate_led.hpp"
#include "platform/input/sources.hpp"
#include "support/unprivileged.hpp"

#include <cerrno>
#include <cstdio>
#include <fcntl.h>
#include <filesystem>
#include <gtest/gtest.h>
#include <linux/input.h>
#include <sys/stat.h>
#include <unistd.h>
#include <vector>

namespace steerseg::test {
namespace {

namespace in = steerseg::platform::input;
namespace fs = std::filesystem;

class EvdevSourceTest : public ::testing::Test {
  protected:
    void SetUp() override {
        dir_ = fs::temp_directory_path() /
               ("steerseg_evdev_" + std::to_string(::getpid()) + "_" +
                ::testing::UnitTest::GetInstance()->current_test_info()->name());
        fs::remove_all(dir_);
        fs::create_directories(dir_);
    }
    void TearDown() override { fs::remove_all(dir_); }

    static input_event event(std::uint16_t type, std::uint16_t code, std::int32_t value) {
        input_event ev{};
        ev.type = type;
        ev.code = code;
        ev.value = value;
        return ev;
    }
    std::string writeFile(const std::vector<input_event>& events) {
        const std::string path = (dir_ / "events.bin").string();
        std::FILE* f = std::fopen(path.c_str(), "wb");
        EXPECT_NE(f, nullptr);
        std::fwrite(events.data(), sizeof(input_event), events.size(), f);
        std::fclose(f);
        return path;
    }
    static in::DeviceSpec spec(const std::string& path) {
        in::DeviceSpec s;
        s.kind = in::DeviceSpec::Kind::PowerMate;
        s.name = "powermate";
        s.path = path;
        return s;
    }
    fs::path dir_;
};

TEST_F(EvdevSourceTest, ReadsRecordsOfAFileWithinMaxRecordsThenGone) {
    const std::string path = writeFile({event(EV_REL, REL_DIAL, 1), event(EV_SYN, SYN_REPORT, 0),
                                        event(EV_KEY, BTN_0, 1), event(EV_SYN, SYN_DROPPED, 0),
                                        event(EV_REL, REL_DIAL, -3)});
    std::string problem;
    auto source = in::openEvdevSource(spec(path), problem);
    ASSERT_NE(source, nullptr) << problem;
    EXPECT_EQ(source->name(), "powermate");
    EXPECT_GE(source->fd(), 0);

    std::vector<in::RawRecord> records;
    EXPECT_EQ(source->read(1.5, 2, records, problem), in::RawSource::ReadStatus::Ok);
    ASSERT_EQ(records.size(), 2U);
    EXPECT_EQ(records[0].kind, in::RawRecord::Kind::Evdev);
    EXPECT_EQ(records[0].device, "powermate");
    EXPECT_EQ(records[0].time, 1.5);
    EXPECT_EQ(records[0].type, EV_REL);
    EXPECT_EQ(records[0].code, REL_DIAL);
    EXPECT_EQ(records[0].value, 1);

    EXPECT_EQ(source->read(2.0, 100, records, problem), in::RawSource::ReadStatus::Gone);
    ASSERT_EQ(records.size(), 5U);
    // SYN_DROPPED is passed on for the decoder to resynchronise.
    EXPECT_EQ(records[3].type, EV_SYN);
    EXPECT_EQ(records[3].code, SYN_DROPPED);
    EXPECT_EQ(records[4].value, -3);
    EXPECT_NE(problem.find("end of input"), std::string::npos) << problem;
}

TEST_F(EvdevSourceTest, FifoIsNonBlockingKeepsPartialRecordsAndEndsWhenTheWriterCloses) {
    const std::string path = (dir_ / "fifo").string();
    ASSERT_EQ(::mkfifo(path.c_str(), 0600), 0);
    // The writer opens after the reader (O_NONBLOCK reader opens at once).
    std::string problem;
    auto source = in::openEvdevSource(spec(path), problem);
    ASSERT_NE(source, nullptr) << problem;
    const int writer = ::open(path.c_str(), O_WRONLY | O_NONBLOCK);
    ASSERT_GE(writer, 0);

    std::vector<in::RawRecord> records;
    EXPECT_EQ(source->read(0.0, 10, records, problem), in::RawSource::ReadStatus::Ok);
    EXPECT_TRUE(records.empty());

    const input_event first = event(EV_REL, REL_DIAL, 7);
    const auto* bytes = reinterpret_cast<const std::uint8_t*>(&first);
    ASSERT_EQ(::write(writer, bytes, 10), 10);
    EXPECT_EQ(source->read(0.1, 10, records, problem), in::RawSource::ReadStatus::Ok);
    EXPECT_TRUE(records.empty()) << "a part of a record is no record";
    ASSERT_EQ(::write(writer, bytes + 10, sizeof first - 10),
              static_cast<ssize_t>(sizeof first - 10));
    EXPECT_EQ(source->read(0.2, 10, records, problem), in::RawSource::ReadStatus::Ok);
    ASSERT_EQ(records.size(), 1U);
    EXPECT_EQ(records[0].value, 7);

    // A flood is read in bounded slices.
    std::vector<input_event> flood(300, event(EV_REL, REL_DIAL, 1));
    ASSERT_EQ(::write(writer, flood.data(), flood.size() * sizeof(input_event)),
              static_cast<ssize_t>(flood.size() * sizeof(input_event)));
    records.clear();
    EXPECT_EQ(source->read(0.3, 100, records, problem), in::RawSource::ReadStatus::Ok);
    EXPECT_EQ(records.size(), 100U);
    EXPECT_EQ(source->read(0.3, 1000, records, problem), in::RawSource::ReadStatus::Ok);
    EXPECT_EQ(records.size(), 300U);

    ::close(writer);
    EXPECT_EQ(source->read(0.4, 10, records, problem), in::RawSource::ReadStatus::Gone);
}

TEST_F(EvdevSourceTest, IndicatorIsNotWrittenIntoARecordedFile) {
    const std::string path = writeFile({event(EV_REL, REL_DIAL, 1)});
    std::string problem;
    auto source = in::openEvdevSource(spec(path), problem);
    ASSERT_NE(source, nullptr) << problem;
    source->setIndicator(in::Indicator::Pulsing);
    EXPECT_EQ(fs::file_size(path), sizeof(input_event));
}

TEST_F(EvdevSourceTest, MissingNodeAndDirectoryAreNamed) {
    std::string problem;
    EXPECT_EQ(in::openEvdevSource(spec((dir_ / "event99").string()), problem), nullptr);
    EXPECT_NE(problem.find("powermate: "), std::string::npos) << problem;
    EXPECT_NE(problem.find("event99: open failed: No such file or directory"), std::string::npos)
        << problem;

    EXPECT_EQ(in::openEvdevSource(spec(dir_.string()), problem), nullptr);
    EXPECT_NE(problem.find("not an evdev node"), std::string::npos) << problem;

    EXPECT_EQ(in::openEvdevSource(spec(""), problem), nullptr);
    EXPECT_NE(problem.find("no evdev path and no vendor/product id"), std::string::npos) << problem;

    in::DeviceSpec byId = spec("");
    byId.vendorId = 0x077d;
    byId.productId = 0x0410;
    if (fs::exists("/dev/input")) {
        GTEST_SKIP() << "/dev/input exists here: a PowerMate might be attached";
    }
    EXPECT_EQ(in::openEvdevSource(byId, problem), nullptr);
    EXPECT_NE(problem.find("no evdev device 077d:0410 in /dev/input"), std::string::npos)
        << problem;
}

TEST_F(EvdevSourceTest, PermissionErrorNamesTheNodeAndTheMissingAccess) {
    const std::string path = writeFile({event(EV_REL, REL_DIAL, 1)});
    ASSERT_EQ(::chmod(path.c_str(), 0), 0);
    // As the kiosk's user meets it: root is denied nothing, so the open runs as nobody.
    const std::string problem = runUnprivileged([&] {
        std::string why;
        return in::openEvdevSource(spec(path), why) == nullptr ? why : "opened";
    });
    EXPECT_NE(problem.find(path + ": open failed: Permission denied"), std::string::npos)
        << problem;
    EXPECT_NE(problem.find("steerseg"), std::string::npos) << problem;
}

TEST(EvdevListing, ReturnsWithoutCrashing) {
    const auto devices = in::listEvdevDevices();
    for (const auto& device : devices) {
        EXPECT_EQ(device.kind, "evdev");
        EXPECT_EQ(device.node.rfind("/dev/input/event", 0), 0U) << device.node;
    }
    if (!fs::exists("/dev/input")) {
        EXPECT_TRUE(devices.empty());
    }
}

TEST(PowerMateLed, PacksTheDriversFields) {
    // drivers/input/misc/powermate.c: brightness bits 0-7, speed 8-16, table 17-18,
    // asleep 19, awake 20.
    in::PowerMateLed led;
    led.brightness = 0x80;
    led.pulseSpeed = 510;
    led.pulseTable = 2;
    led.pulseAsleep = true;
    led.pulseAwake = true;
    EXPECT_EQ(in::packPowerMateLed(led), 0x80 | (510 << 8) | (2 << 17) | (1 << 19) | (1 << 20));

    led = {};
    led.brightness = 300; // clamped: must not spill into the speed bits
    led.pulseSpeed = -4;
    led.pulseTable = 7;
    EXPECT_EQ(in::packPowerMateLed(led), 255 | (2 << 17));

    EXPECT_EQ(in::packPowerMateLed(in::powerMateLedFor(in::Indicator::Off)), 255 << 8);
    EXPECT_EQ(in::packPowerMateLed(in::powerMateLedFor(in::Indicator::Steady)), 255 | (255 << 8));
    EXPECT_EQ(in::packPowerMateLed(in::powerMateLedFor(in::Indicator::Pulsing)),
              (255 << 8) | (1 << 20));
}

} // namespace
} // namespace steerseg::test
