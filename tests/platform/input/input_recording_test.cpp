// The recording file: every record kind round-trips exactly (time to the microsecond), each
// kind of malformed line is one problem and skipped, limits hold, and recordings under
// tests/data/input/ replay through the decoders.
#include "input_test_util.hpp"
#include "platform/input/decoders.hpp"
#include "platform/input/recording.hpp"

#include <gtest/gtest.h>
#include <sstream>

namespace steerseg::test {
namespace {

using platform::input::ControlEvent;
using platform::input::DeviceSpec;
using platform::input::formatRecordLine;
using platform::input::parseRecording;
using platform::input::parseRecordLine;
using platform::input::RawRecord;
using platform::input::readRecording;
using platform::input::Recording;
using Strings = std::vector<std::string>;

const std::string kDir = STEERSEG_INPUT_DATA_DIR;

void expectSame(const RawRecord& a, const RawRecord& b) {
    EXPECT_EQ(a.kind, b.kind);
    EXPECT_EQ(a.time, b.time);
    EXPECT_EQ(a.device, b.device);
    EXPECT_EQ(a.bytes, b.bytes);
    EXPECT_EQ(a.type, b.type);
    EXPECT_EQ(a.code, b.code);
    EXPECT_EQ(a.value, b.value);
    EXPECT_EQ(a.active, b.active);
}

TEST(InputRecording, EveryKindRoundTripsExactly) {
    std::vector<RawRecord> records;
    RawRecord d = hidDescriptor(0.0, std::vector<std::uint8_t>(4096));
    for (std::size_t i = 0; i < d.bytes.size(); ++i) {
        d.bytes[i] = static_cast<std::uint8_t>(i * 37);
    }
    records.push_back(d);
    records.push_back(hidReport(0.016, {0x04, 0x03, 0xFF, 0x00, 0xAB}));
    records.push_back(evdev(123456.789012, 65535, 65535, -2147483647 - 1));
    records.push_back(evdev(123456.789013, 2, 7, 2147483647));
    records.push_back(gpioEdge(0.5, true));
    records.push_back(gpioEdge(0.5, false));
    records.push_back(plugRecord(999999999.999999, false));
    records.push_back(plugRecord(1.000001, true));
    for (RawRecord& r : records) {
        r.device = "dev_0";
        std::string problem;
        const std::string line = formatRecordLine(r);
        const auto back = parseRecordLine(line, problem);
        ASSERT_TRUE(back) << line << ": " << problem;
        expectSame(*back, r);
        EXPECT_EQ(formatRecordLine(*back), line);
    }
    EXPECT_EQ(formatRecordLine(records[1]), "0.016000 dev_0 hid 0403ff00ab");
    EXPECT_EQ(formatRecordLine(records[2]), "123456.789012 dev_0 evdev 65535 65535 -2147483648");
    EXPECT_EQ(formatRecordLine(records[4]), "0.500000 dev_0 gpio 1");
    EXPECT_EQ(formatRecordLine(records[6]), "999999999.999999 dev_0 unplug");
    EXPECT_EQ(formatRecordLine(records[7]), "1.000001 dev_0 plug");
}

TEST(InputRecording, BlankCommentAndTolerantSpacing) {
    std::string problem = "stale";
    EXPECT_FALSE(parseRecordLine("", problem));
    EXPECT_EQ(problem, "");
    EXPECT_FALSE(parseRecordLine("   \t  ", problem));
    EXPECT_EQ(problem, "");
    EXPECT_FALSE(parseRecordLine("# steerseg input recording 1", problem));
    EXPECT_EQ(problem, "");
    EXPECT_FALSE(parseRecordLine("  # a note", problem));
    EXPECT_EQ(problem, "");
    const auto r = parseRecordLine("\t2.5   shuttle\thid  0A0b\r", problem);
    ASSERT_TRUE(r) << problem;
    EXPECT_EQ(r->bytes, (std::vector<std::uint8_t>{0x0A, 0x0B}));
    EXPECT_EQ(r->time, 2.5);
}

TEST(InputRecording, EachMalformedLineKindIsOneProblem) {
    const std::vector<std::pair<std::string, std::string>> cases{
        {"# steerseg input recording 2", "recording format '2', this build reads format 1"},
        {"nonsense", "expected TIME DEVICE KIND ..."},
        {"0.1 dial", "expected TIME DEVICE KIND ..."},
        {"x dial plug", "time 'x' is not seconds from the start"},
        {"-1 dial plug", "time '-1' is not seconds from the start"},
        {"-0 dial plug", "time '-0' is not seconds from the start"},
        {"nan dial plug", "time 'nan' is not seconds from the start"},
        {"inf dial plug", "time 'inf' is not seconds from the start"},
        {"1e9 dial plug", "time '1e9' is not seconds from the start"},
        {"0.1 Dial plug", "device 'Dial' is not a name of a-z, 0-9, _ (at most 64)"},
        {"0.1 di-al plug", "device 'di-al' is not a name of a-z, 0-9, _ (at most 64)"},
        {"0.1 " + std::string(65, 'a') + " plug",
         "device 'aaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaa...' is not a name of a-z, 0-9, _ (at most 64)"},
        {"0.1 dial wiggle 1",
         "unknown record kind 'wiggle' (hid-descriptor, hid, evdev, gpio, unplug, plug)"},
        {"0.1 dial hid", "hid takes one hex field"},
        {"0.1 dial hid 01 02", "hid takes one hex field"},
        {"0.1 dial hid 012", "odd number of hex digits in '012'"},
        {"0.1 dial hid 0g", "not hex: '0g'"},
        {"0.1 dial hid " + std::string(8194, 'a'), "4097 bytes, over the 4096-byte limit"},
        {"0.1 dial hid-descriptor zz", "not hex: 'zz'"},
        {"0.1 pm evdev 1 2", "evdev takes type, code and value (decimal)"},
        {"0.1 pm evdev 1 2 3 4", "evdev takes type, code and value (decimal)"},
        {"0.1 pm evdev 1 2 x",
         "evdev type, code and value must be decimal (0..65535, 0..65535, int32)"},
        {"0.1 pm evdev 70000 2 1",
         "evdev type, code and value must be decimal (0..65535, 0..65535, int32)"},
        {"0.1 pm evdev 1 2 2147483648",
         "evdev type, code and value must be decimal (0..65535, 0..65535, int32)"},
        {"0.1 pedal gpio 2", "gpio takes 1 or 0, not '2'"},
        {"0.1 pedal gpio", "gpio takes 1 or 0"},
        {"0.1 pedal unplug now", "unplug takes nothing after it"},
        {"0.1 pedal plug 1 2 3 4 5 6 7 8", "plug takes nothing after it"},
        {std::string(16 * 1024 + 1, '1'), "line over 16 KiB"},
    };
    for (const auto& [line, expected] : cases) {
        std::string problem;
        EXPECT_FALSE(parseRecordLine(line, problem)) << line.substr(0, 80);
        EXPECT_EQ(problem, expected) << line.substr(0, 80);
    }
}

TEST(InputRecording, AFileKeepsItsGoodLinesAndNamesTheBadOnesByLine) {
    const Recording rec = readRecording(kDir + "/mixed_with_errors.rec");
    ASSERT_EQ(rec.records.size(), 3U);
    EXPECT_EQ(rec.records[0].kind, RawRecord::Kind::HidDescriptor);
    EXPECT_EQ(rec.records[1].bytes, (std::vector<std::uint8_t>{0x01})); // its line ends in CRLF
    EXPECT_EQ(rec.records[2].kind, RawRecord::Kind::Plugged);
    EXPECT_EQ(rec.records[2].time, 1.3);
    ASSERT_EQ(rec.problems.size(), 14U);
    const std::string prefix = kDir + "/mixed_with_errors.rec:";
    EXPECT_EQ(rec.problems[0], prefix + "5: expected TIME DEVICE KIND ...");
    EXPECT_EQ(rec.problems[13], prefix + "18: time goes back before the previous line's (skipped)");
}

TEST(InputRecording, LimitsOnLinesRecordsAndProblems) {
    std::stringstream in;
    in << "0.1 a plug\n" << std::string(100000, 'x') << "\n0.2 a plug\n0.3 a plug\n0.4 a plug\n";
    const Recording rec = parseRecording(in, "s", 2);
    ASSERT_EQ(rec.records.size(), 2U);
    EXPECT_EQ(rec.problems, (Strings{"s:2: line over 16 KiB (skipped)",
                                     "s:4: over 2 records: this line and the rest dropped"}));

    std::stringstream bad;
    for (int i = 0; i < 5000; ++i) {
        bad << "junk\n";
    }
    const Recording flood = parseRecording(bad, "f");
    ASSERT_EQ(flood.problems.size(), 101U);
    EXPECT_EQ(flood.problems.back(), "f: ... and 4900 more problems");

    std::stringstream noNewline;
    noNewline << "0.5 a gpio 1";
    EXPECT_EQ(parseRecording(noNewline, "n").records.size(), 1U);
}

TEST(InputRecording, MissingFileOrFolderIsOneProblem) {
    const Recording missing = readRecording(kDir + "/no_such.rec");
    EXPECT_TRUE(missing.records.empty());
    ASSERT_EQ(missing.problems.size(), 1U);
    EXPECT_NE(missing.problems[0].find("cannot open: No such file"), std::string::npos);
    const Recording folder = readRecording(kDir);
    ASSERT_EQ(folder.problems.size(), 1U);
    EXPECT_NE(folder.problems[0].find("is a folder"), std::string::npos);
}

// Replays a recording through one decoder per device, ticking at each record's time and once
// well after the end, as the live loop does.
std::vector<ControlEvent> replay(const std::string& file, DeviceSpec spec) {
    const Recording rec = readRecording(kDir + "/" + file);
    EXPECT_TRUE(rec.problems.empty()) << rec.problems.front();
    auto decoder = platform::input::makeDecoder(spec);
    std::vector<ControlEvent> out;
    for (const RawRecord& r : rec.records) {
        EXPECT_EQ(r.device, spec.name);
        decoder->tick(r.time, out);
        decoder->feed(r, out);
    }
    decoder->tick(rec.records.back().time + 10.0, out);
    EXPECT_TRUE(decoder->takeProblems().empty());
    return out;
}

TEST(InputRecording, ShuttleRecordingReplays) {
    DeviceSpec spec;
    spec.kind = DeviceSpec::Kind::Shuttle;
    spec.name = "shuttle";
    const auto events = replay("shuttle_turn_unplug.rec", spec);
    EXPECT_EQ(describe(events),
              (Strings{"shuttle_jog step 1", "shuttle_jog step 1", "shuttle_jog step 1",
                       "shuttle_ring pos 0.429", "shuttle_ring pos 0.000", "shuttle_button5 press",
                       "shuttle_ring pos 0.714", "shuttle_button5 release",
                       "shuttle_ring pos 0.000", "shuttle_jog step -1"}));
    EXPECT_DOUBLE_EQ(events[7].time, 0.5);
}

TEST(InputRecording, PedalRecordingReplays) {
    DeviceSpec spec;
    spec.kind = DeviceSpec::Kind::GpioInput;
    spec.name = "pedal";
    const auto events = replay("pedal_bounce.rec", spec);
    EXPECT_EQ(describe(events), (Strings{"pedal press", "pedal release"}));
    EXPECT_DOUBLE_EQ(events[0].time, 1.0);
    EXPECT_DOUBLE_EQ(events[1].time, 3.0);
}

TEST(InputRecording, PowerMateRecordingReplays) {
    DeviceSpec spec;
    spec.kind = DeviceSpec::Kind::PowerMate;
    spec.name = "powermate";
    const auto events = replay("powermate_turn.rec", spec);
    EXPECT_EQ(describe(events), (Strings{"powermate_turn step 2", "powermate_press press",
                                         "powermate_turn step -1", "powermate_press release"}));
}

} // namespace
} // namespace steerseg::test
