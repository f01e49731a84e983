// The shuttle and radial decoders: jog wrap-around both ways, the ring's return to centre,
// buttons by bit, short, over-long and garbage reports, unplug in the middle of a turn or press.
#include "input_test_util.hpp"
#include "platform/input/decoders.hpp"

#include <gtest/gtest.h>

namespace steerseg::test {
namespace {

using platform::input::DeviceSpec;
using platform::input::makeDecoder;
using platform::input::RawRecord;
using Strings = std::vector<std::string>;

// The ShuttlePRO v2 (0b33:0030) unless another product id is given.
std::unique_ptr<platform::input::Decoder> shuttle(std::uint16_t productId = 0x0030) {
    DeviceSpec spec;
    spec.kind = DeviceSpec::Kind::Shuttle;
    spec.name = "shuttle";
    spec.vendorId = 0x0b33;
    spec.productId = productId;
    return makeDecoder(spec);
}

std::unique_ptr<platform::input::Decoder> radial() {
    DeviceSpec spec;
    spec.kind = DeviceSpec::Kind::Radial;
    spec.name = "dial";
    return makeDecoder(spec);
}

RawRecord report(double t, int ring, int jog, unsigned buttons) {
    return hidReport(t, {static_cast<std::uint8_t>(ring), static_cast<std::uint8_t>(jog), 0,
                         static_cast<std::uint8_t>(buttons & 0xFFU),
                         static_cast<std::uint8_t>(buttons >> 8)});
}

TEST(InputShuttle, JogWrapsAroundBothWaysAfterTheFirstReport) {
    auto d = shuttle();
    const auto events =
        feedAll(*d, {report(0.0, 0, 254, 0), report(0.1, 0, 255, 0), report(0.2, 0, 0, 0),
                     report(0.3, 0, 1, 0), report(0.4, 0, 0, 0), report(0.5, 0, 255, 0),
                     report(0.6, 0, 250, 0), report(0.7, 0, 3, 0)});
    EXPECT_EQ(describe(events),
              (Strings{"shuttle_jog step 1", "shuttle_jog step 1", "shuttle_jog step 1",
                       "shuttle_jog step -1", "shuttle_jog step -1", "shuttle_jog step -5",
                       "shuttle_jog step 9"}));
    EXPECT_DOUBLE_EQ(events[0].time, 0.1);
    EXPECT_TRUE(d->takeProblems().empty());
}

TEST(InputShuttle, RingPositionsAndReturnToCentre) {
    auto d = shuttle();
    const auto events =
        feedAll(*d, {report(0.0, 0, 10, 0), report(0.1, 3, 10, 0), report(0.2, 7, 10, 0),
                     report(0.3, 7, 10, 0), report(0.4, 0, 10, 0), report(0.5, -7, 10, 0),
                     report(0.6, 0, 10, 0)});
    EXPECT_EQ(describe(events),
              (Strings{"shuttle_ring pos 0.429", "shuttle_ring pos 1.000", "shuttle_ring pos 0.000",
                       "shuttle_ring pos -1.000", "shuttle_ring pos 0.000"}));
}

TEST(InputShuttle, ProButtonsAreNamedByBit) {
    auto d = shuttle();
    const auto events = feedAll(*d, {report(0.0, 0, 0, 0x0010), report(0.1, 0, 0, 0x0100),
                                     report(0.2, 0, 0, 0x4001), report(0.3, 0, 0, 0x0000)});
    EXPECT_EQ(describe(events),
              (Strings{"shuttle_button5 press", "shuttle_button9 press", "shuttle_button5 release",
                       "shuttle_button1 press", "shuttle_button15 press", "shuttle_button9 release",
                       "shuttle_button1 release", "shuttle_button15 release"}));
}

TEST(InputShuttle, XpressButtonsAreNumberedOneToFiveFromBitFour) {
    auto d = shuttle(0x0020);
    const auto events = feedAll(*d, {report(0.0, 0, 0, 0x0010), report(0.1, 0, 0, 0x0100),
                                     report(0.2, 0, 0, 0x0000), report(0.3, 0, 0, 0x0001)});
    EXPECT_EQ(describe(events), (Strings{"shuttle_button1 press", "shuttle_button5 press",
                                         "shuttle_button1 release", "shuttle_button5 release"}));
    EXPECT_EQ(d->takeProblems(),
              (Strings{"shuttle: button bits 0x1 set, no such button (report dropped)"}));
}

TEST(InputShuttle, ShortLongAndGarbageReportsAreProblemsNotEvents) {
    auto d = shuttle();
    std::vector<platform::input::ControlEvent> out;
    d->feed(report(0.0, 0, 100, 0), out);
    d->feed(hidReport(0.1, {0x01, 0x02, 0x00}), out);
    d->feed(hidReport(0.2, {0x00, 0x65, 0x00, 0x00, 0x00, 0x00}), out);
    d->feed(hidReport(0.3, {}), out);
    d->feed(report(0.4, 0x40, 101, 0), out);   // ring 64
    d->feed(report(0.5, 0, 102, 0x8000), out); // no button 16
    d->feed(evdev(0.6, 2, 7, 1), out);
    EXPECT_TRUE(out.empty());
    const Strings problems = d->takeProblems();
    EXPECT_EQ(problems, (Strings{"shuttle: report of 3 bytes, expected 5",
                                 "shuttle: report of 6 bytes, expected 5",
                                 "shuttle: report of 0 bytes, expected 5",
                                 "shuttle: ring position 64 outside -7..7 (report dropped)",
                                 "shuttle: button bits 0x8000 set, no such button (report dropped)",
                                 "shuttle: not a HID record (ignored)"}));
    EXPECT_TRUE(d->takeProblems().empty());
    // The reference survived the garbage: 100 -> 103 is 3 steps.
    d->feed(report(0.7, 0, 103, 0), out);
    EXPECT_EQ(describe(out), (Strings{"shuttle_jog step 3"}));
}

TEST(InputShuttle, AFloodOfGarbageKeepsAFewLinesAndACount) {
    auto d = shuttle();
    std::vector<platform::input::ControlEvent> out;
    for (int i = 0; i < 1000; ++i) {
        d->feed(hidReport(i * 0.001, {0x01}), out);
    }
    const Strings problems = d->takeProblems();
    ASSERT_EQ(problems.size(), 33U);
    EXPECT_EQ(problems.back(), "... and 968 more");
}

TEST(InputShuttle, UnplugInTheMiddleOfATurnAndAPressReleasesEverything) {
    auto d = shuttle();
    std::vector<platform::input::ControlEvent> out;
    for (const auto& r : {report(0.0, 0, 50, 0), report(0.1, 5, 51, 0x0020)}) {
        d->feed(r, out);
    }
    out.clear();
    d->feed(plugRecord(0.2, false), out);
    EXPECT_EQ(describe(out), (Strings{"shuttle_button6 release", "shuttle_ring pos 0.000"}));
    EXPECT_DOUBLE_EQ(out[0].time, 0.2);
    out.clear();
    // Replugged: the first report sets the jog reference again, whatever the counter says.
    d->feed(plugRecord(0.5, true), out);
    d->feed(report(0.6, 0, 200, 0), out);
    d->feed(report(0.7, 0, 201, 0), out);
    EXPECT_EQ(describe(out), (Strings{"shuttle_jog step 1"}));
    // reset() itself does the same, and twice gives nothing more.
    out.clear();
    d->feed(report(0.8, -2, 201, 0x0001), out);
    out.clear();
    d->reset(0.9, out);
    d->reset(1.0, out);
    EXPECT_EQ(describe(out), (Strings{"shuttle_button1 release", "shuttle_ring pos 0.000"}));
}

// The Surface Dial's report 1: button bit 0, dial int16 at byte 1, X, Y, width.
RawRecord dialReport(double t, bool button, int dial) {
    const auto v = static_cast<std::uint16_t>(static_cast<std::int16_t>(dial));
    return hidReport(t, {0x01, static_cast<std::uint8_t>(button ? 1 : 0),
                         static_cast<std::uint8_t>(v & 0xFFU), static_cast<std::uint8_t>(v >> 8), 0,
                         0, 0, 0, 0});
}

TEST(InputRadial, SurfaceDialTurnsAndPresses) {
    auto d = radial();
    std::vector<platform::input::ControlEvent> out;
    d->feed(dialReport(0.0, false, 1), out); // before the descriptor
    d->feed(hidDescriptor(0.1, hexBytes(kSurfaceDialHex)), out);
    d->feed(dialReport(0.2, false, 3), out);
    d->feed(dialReport(0.3, true, 0), out);
    d->feed(dialReport(0.4, true, -2), out);
    d->feed(dialReport(0.5, false, 0), out);
    d->feed(dialReport(0.6, false, -32767), out);
    EXPECT_EQ(describe(out), (Strings{"dial_turn step 3", "dial_press press", "dial_turn step -2",
                                      "dial_press release", "dial_turn step -32767"}));
    EXPECT_EQ(d->takeProblems(),
              (Strings{"dial: report before a usable report descriptor (ignored)"}));
}

TEST(InputRadial, MicrosoftSampleLayoutDecodesItsOddOffsetDial) {
    auto d = radial();
    std::vector<platform::input::ControlEvent> out;
    d->feed(hidDescriptor(0.0, hexBytes(kMicrosoftSampleRadialHex)), out);
    d->feed(hidReport(0.1, {0x01, 0xF7, 0xFF, 0, 0, 0, 0, 0, 0}), out); // press, dial -5
    d->feed(hidReport(0.2, {0x01, 0x06, 0x00, 0, 0, 0, 0, 0, 0}), out); // release, dial +3
    EXPECT_EQ(describe(out), (Strings{"dial_turn step -5", "dial_press press", "dial_turn step 3",
                                      "dial_press release"}));
    EXPECT_TRUE(d->takeProblems().empty());
}

TEST(InputRadial, UnknownIdsWrongLengthsAndUnplugMidPress) {
    auto d = radial();
    std::vector<platform::input::ControlEvent> out;
    d->feed(hidDescriptor(0.0, hexBytes(kSurfaceDialHex)), out);
    d->feed(hidReport(0.1, {0x02, 0, 0, 0, 0, 0, 0, 0, 0}), out);
    d->feed(hidReport(0.2, {0x01, 0, 5}), out);
    d->feed(hidReport(0.3, std::vector<std::uint8_t>(64, 0x01)), out);
    d->feed(hidReport(0.4, {}), out);
    d->feed(gpioEdge(0.5, true), out);
    EXPECT_TRUE(out.empty());
    EXPECT_EQ(
        d->takeProblems(),
        (Strings{"dial: report id 2 not in the descriptor (ignored)",
                 "dial: report 1 of 3 bytes, expected 9", "dial: report 1 of 64 bytes, expected 9",
                 "dial: empty report", "dial: not a HID record (ignored)"}));
    d->feed(dialReport(0.6, true, 4), out);
    d->feed(plugRecord(0.7, false), out);
    EXPECT_EQ(describe(out),
              (Strings{"dial_turn step 4", "dial_press press", "dial_press release"}));
}

TEST(InputRadial, HandMadeLayoutsWithReportIdsAndAWheelFallback) {
    auto d = radial();
    std::vector<platform::input::ControlEvent> out;
    // Report 3: buttons 1..3, a 5-bit signed Dial at bit 3. Report 4: a 12-bit signed Wheel.
    d->feed(hidDescriptor(0.0, hexBytes("05 01 09 0E A1 01 85 03 05 09 19 01 29 03 15 00 25 01 "
                                        "75 01 95 03 81 02 A4 05 01 09 37 15 F0 25 0F 75 05 95 "
                                        "01 81 06 B4 75 05 95 01 81 03 85 04 05 01 09 38 16 00 "
                                        "F8 26 FF 07 75 0C 95 01 81 06 75 04 81 03 C0")),
            out);
    d->feed(hidReport(0.1, {0x03, 0xF9, 0x00}), out); // button 1, dial -1
    d->feed(hidReport(0.2, {0x04, 0x00, 0x08}), out); // the Wheel is not used: a Dial exists
    d->feed(hidReport(0.3, {0x03, 0x10, 0x00}), out); // dial +2, button up
    EXPECT_EQ(describe(out), (Strings{"dial_turn step -1", "dial_press press", "dial_turn step 2",
                                      "dial_press release"}));
    EXPECT_TRUE(d->takeProblems().empty());

    // Without a Dial the Wheel turns, and a controller without a button still turns.
    out.clear();
    d->feed(hidDescriptor(1.0, hexBytes("05 01 09 0E A1 01 09 38 15 81 25 7F 75 08 95 01 81 06 "
                                        "C0")),
            out);
    d->feed(hidReport(1.1, {0xFE}), out);
    EXPECT_EQ(describe(out), (Strings{"dial_turn step -2"}));

    // A mouse wheel outside a multi-axis controller is not a radial controller.
    d->feed(hidDescriptor(2.0, hexBytes("05 01 09 02 A1 01 09 38 15 81 25 7F 75 08 95 01 81 06 "
                                        "C0")),
            out);
    d->feed(hidReport(2.1, {0x01}), out);
    const Strings problems = d->takeProblems();
    ASSERT_EQ(problems.size(), 2U);
    EXPECT_NE(problems[0].find("no relative Dial or Wheel"), std::string::npos);
    EXPECT_EQ(problems[1], "dial: report before a usable report descriptor (ignored)");
    // A descriptor the parser refuses is named too.
    d->feed(hidDescriptor(3.0, hexBytes("B4")), out);
    EXPECT_NE(d->takeProblems().at(0).find("Pop without a Push"), std::string::npos);
}

TEST(InputRadial, ANewDescriptorReleasesWhatTheOldLayoutHeld) {
    auto d = radial();
    std::vector<platform::input::ControlEvent> out;
    d->feed(hidDescriptor(0.0, hexBytes(kSurfaceDialHex)), out);
    d->feed(dialReport(0.1, true, 0), out);
    d->feed(hidDescriptor(0.2, hexBytes(kSurfaceDialHex)), out);
    EXPECT_EQ(describe(out), (Strings{"dial_press press", "dial_press release"}));
}

TEST(InputDecoderFactory, EachKindGetsItsDecoderAndLedsNone) {
    DeviceSpec spec;
    spec.name = "x";
    for (const auto kind : {DeviceSpec::Kind::Shuttle, DeviceSpec::Kind::Radial,
                            DeviceSpec::Kind::PowerMate, DeviceSpec::Kind::GpioInput}) {
        spec.kind = kind;
        EXPECT_TRUE(makeDecoder(spec));
    }
    spec.kind = DeviceSpec::Kind::GpioLed;
    EXPECT_FALSE(makeDecoder(spec));
}

} // namespace
} // namespace steerseg::test
