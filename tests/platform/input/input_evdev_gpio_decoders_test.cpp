// The PowerMate decoder (evdev frames, autorepeat, SYN_DROPPED) and the debounced GPIO line
// (contact bounce ending pressed or released, held pedal, unplug while held).
#include "input_test_util.hpp"
#include "platform/input/decoders.hpp"

#include <gtest/gtest.h>
#include <linux/input-event-codes.h>

namespace steerseg::test {
namespace {

using platform::input::ControlEvent;
using platform::input::DeviceSpec;
using platform::input::RawRecord;
using Strings = std::vector<std::string>;

std::unique_ptr<platform::input::Decoder> powermate() {
    DeviceSpec spec;
    spec.kind = DeviceSpec::Kind::PowerMate;
    spec.name = "powermate";
    return platform::input::makeDecoder(spec);
}

std::unique_ptr<platform::input::Decoder> pedal(double debounce = 0.02) {
    DeviceSpec spec;
    spec.kind = DeviceSpec::Kind::GpioInput;
    spec.name = "pedal";
    spec.debounceSeconds = debounce;
    return platform::input::makeDecoder(spec);
}

RawRecord turn(double t, int v) {
    return evdev(t, EV_REL, REL_DIAL, v);
}
RawRecord button(double t, int v) {
    return evdev(t, EV_KEY, BTN_0, v);
}
RawRecord syn(double t) {
    return evdev(t, EV_SYN, SYN_REPORT, 0);
}

TEST(InputPowerMate, TurnsSumWithinAFrameAndKeepTheirOrderAroundPresses) {
    auto d = powermate();
    const auto events =
        feedAll(*d, {turn(0.0, 1), turn(0.0, 2), syn(0.0), turn(0.1, -1), button(0.1, 1),
                     turn(0.1, 1), syn(0.1), button(0.2, 2), syn(0.2), button(0.3, 2), syn(0.3),
                     button(0.4, 0), syn(0.4), turn(0.5, 0), syn(0.5)});
    EXPECT_EQ(describe(events),
              (Strings{"powermate_turn step 3", "powermate_turn step -1", "powermate_press press",
                       "powermate_turn step 1", "powermate_press release"}));
    EXPECT_TRUE(d->takeProblems().empty());
}

TEST(InputPowerMate, NothingIsSentBeforeItsSynReport) {
    auto d = powermate();
    std::vector<ControlEvent> out;
    d->feed(turn(0.0, 4), out);
    d->feed(button(0.0, 1), out);
    EXPECT_TRUE(out.empty());
    d->feed(syn(0.0), out);
    EXPECT_EQ(out.size(), 2U);
}

TEST(InputPowerMate, SynDroppedDiscardsUntilTheNextSynReport) {
    auto d = powermate();
    const auto events =
        feedAll(*d, {turn(0.0, 5), evdev(0.0, EV_SYN, SYN_DROPPED, 0), button(0.0, 1), turn(0.0, 7),
                     syn(0.0), turn(0.1, 1), syn(0.1)});
    EXPECT_EQ(describe(events), (Strings{"powermate_turn step 1"}));
    const Strings problems = d->takeProblems();
    ASSERT_EQ(problems.size(), 1U);
    EXPECT_NE(problems[0].find("SYN_DROPPED"), std::string::npos);
}

TEST(InputPowerMate, OtherEventsAreIgnoredSilentlyAndOtherRecordsAreProblems) {
    auto d = powermate();
    std::vector<ControlEvent> out;
    for (const auto& r : {evdev(0.0, EV_MSC, MSC_PULSELED, 255), evdev(0.0, EV_REL, REL_X, 3),
                          evdev(0.0, EV_KEY, KEY_A, 1), evdev(0.0, 0x1F, 0xFFFF, -1), syn(0.0)}) {
        d->feed(r, out);
    }
    EXPECT_TRUE(out.empty());
    EXPECT_TRUE(d->takeProblems().empty());
    d->feed(hidReport(0.1, {1, 2}), out);
    d->feed(button(0.2, 7), out);
    EXPECT_EQ(d->takeProblems(), (Strings{"powermate: not an evdev record (ignored)",
                                          "powermate: BTN_0 value 7 (ignored)"}));
}

TEST(InputPowerMate, UnplugMidPressReleasesAndDropsTheOpenFrame) {
    auto d = powermate();
    std::vector<ControlEvent> out;
    for (const auto& r : {button(0.0, 1), syn(0.0), turn(0.1, 3)}) {
        d->feed(r, out);
    }
    out.clear();
    d->feed(plugRecord(0.2, false), out);
    d->feed(syn(0.3), out); // the turn of the open frame is gone
    EXPECT_EQ(describe(out), (Strings{"powermate_press release"}));
    EXPECT_DOUBLE_EQ(out[0].time, 0.2);
}

TEST(InputPowerMate, AStreamWithoutSynStaysBounded) {
    auto d = powermate();
    std::vector<ControlEvent> out;
    for (int i = 0; i < 10000; ++i) {
        d->feed(button(0.0, i % 2 == 0 ? 1 : 0), out);
    }
    EXPECT_EQ(out.size() % 64, 0U); // committed in frames of 64, none lost
    EXPECT_GE(out.size(), 9984U);
    for (int i = 0; i < 100000; ++i) {
        d->feed(turn(0.0, 1000000), out);
    }
    d->feed(syn(0.0), out);
    EXPECT_GT(out.back().steps, 0); // saturated, not overflowed
}

TEST(InputGpioLine, CleanPressAndHeldPedal) {
    auto d = pedal();
    std::vector<ControlEvent> out;
    d->feed(gpioEdge(0.0, true), out);
    for (double t = 0.01; t < 3.0; t += 0.25) {
        d->tick(t, out); // held: no repeats
    }
    d->feed(gpioEdge(3.0, false), out);
    d->tick(4.0, out);
    EXPECT_EQ(describe(out), (Strings{"pedal press", "pedal release"}));
    EXPECT_DOUBLE_EQ(out[0].time, 0.0); // taken at once, not after the debounce time
    EXPECT_DOUBLE_EQ(out[1].time, 3.0);
}

TEST(InputGpioLine, ABounceEndingPressedIsOnePress) {
    auto d = pedal();
    std::vector<ControlEvent> out;
    for (const auto& r : {gpioEdge(0.000, true), gpioEdge(0.002, false), gpioEdge(0.004, true),
                          gpioEdge(0.006, false), gpioEdge(0.008, true)}) {
        d->feed(r, out);
    }
    d->tick(0.020, out); // 12 ms since the last edge: not settled yet
    d->tick(0.030, out);
    EXPECT_EQ(describe(out), (Strings{"pedal press"}));
}

TEST(InputGpioLine, ABounceEndingReleasedIsPressThenRelease) {
    auto d = pedal();
    std::vector<ControlEvent> out;
    for (const auto& r : {gpioEdge(0.000, true), gpioEdge(0.003, false), gpioEdge(0.005, true),
                          gpioEdge(0.009, false)}) {
        d->feed(r, out);
    }
    d->tick(0.028, out);
    EXPECT_EQ(describe(out), (Strings{"pedal press"}));
    d->tick(0.030, out);
    EXPECT_EQ(describe(out), (Strings{"pedal press", "pedal release"}));
    EXPECT_DOUBLE_EQ(out[1].time, 0.030);
}

TEST(InputGpioLine, ReleaseBounceAndSettlingWithoutATick) {
    auto d = pedal();
    std::vector<ControlEvent> out;
    for (const auto& r : {gpioEdge(0.0, true), gpioEdge(1.000, false), gpioEdge(1.002, true),
                          gpioEdge(1.004, false),
                          // bounced back to pressed; no tick comes, the next edge settles it
                          gpioEdge(1.006, true), gpioEdge(2.0, false)}) {
        d->feed(r, out);
    }
    EXPECT_EQ(describe(out),
              (Strings{"pedal press", "pedal release", "pedal press", "pedal release"}));
    EXPECT_DOUBLE_EQ(out[2].time, 2.0);
}

TEST(InputGpioLine, UnplugWhileHeldReleasesAndZeroDebounceTakesEveryEdge) {
    auto d = pedal();
    std::vector<ControlEvent> out;
    d->feed(gpioEdge(0.0, true), out);
    d->feed(plugRecord(0.5, false), out);
    d->tick(1.0, out);
    d->feed(gpioEdge(1.0, true), out); // after replug the line is quiet again
    EXPECT_EQ(describe(out), (Strings{"pedal press", "pedal release", "pedal press"}));

    auto raw = pedal(0.0);
    out.clear();
    for (const auto& r : {gpioEdge(0.0, true), gpioEdge(0.0, false), gpioEdge(0.001, true)}) {
        raw->feed(r, out);
    }
    EXPECT_EQ(describe(out), (Strings{"pedal press", "pedal release", "pedal press"}));
    raw->feed(turn(0.1, 1), out);
    EXPECT_EQ(raw->takeProblems(), (Strings{"pedal: not a GPIO record (ignored)"}));
}

} // namespace
} // namespace steerseg::test
