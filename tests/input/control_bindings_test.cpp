// Control events -> workflow actions: acceleration, the ring's repeat rate, hold bindings,
// unbound controls, last touch wins, and a knob driven past a parameter's range.
#include "config/kiosk_config.hpp"
#include "input/control_bindings.hpp"
#include "support/workflow_rig.hpp"

#include <gtest/gtest.h>
#include <variant>

namespace steerseg::test {
namespace {

using input::ControlBindings;
using model::Action;
using platform::input::ControlEvent;

ControlEvent step(const char* control, int steps, double time) {
    return {ControlEvent::Kind::Step, time, control, steps, 0.0};
}
ControlEvent ring(const char* control, double position, double time) {
    return {ControlEvent::Kind::Position, time, control, 0, position};
}
ControlEvent press(const char* control, double time) {
    return {ControlEvent::Kind::Press, time, control, 0, 0.0};
}
ControlEvent release(const char* control, double time) {
    return {ControlEvent::Kind::Release, time, control, 0, 0.0};
}

ControlBindings defaults() {
    const config::KioskConfig c = config::defaultConfig();
    return ControlBindings(c.bindings.knobs, c.bindings.buttons);
}

double nudged(const std::vector<Action>& actions) {
    double total = 0.0;
    for (const Action& a : actions) {
        if (const auto* n = std::get_if<model::NudgeSelected>(&a)) {
            total += n->steps;
        }
    }
    return total;
}

TEST(ControlBindings, AccelerationCurve) {
    EXPECT_EQ(input::stepAcceleration(0.0), 1.0);
    EXPECT_EQ(input::stepAcceleration(3.0), 1.0);
    EXPECT_DOUBLE_EQ(input::stepAcceleration(6.0), 2.0);
    EXPECT_DOUBLE_EQ(input::stepAcceleration(12.0), 4.0);
    EXPECT_EQ(input::stepAcceleration(1000.0), 10.0);
    EXPECT_EQ(input::stepAcceleration(std::nan("")), 1.0);
}

TEST(ControlBindings, SlowJogIsFineStepsAFlickCountsMore) {
    ControlBindings b = defaults();
    std::vector<Action> out;
    for (int i = 0; i < 10; ++i) { // one detent every 50 ms: 2 per 100 ms
        b.feed(step("shuttle_jog", 1, 0.05 * i), out);
    }
    EXPECT_DOUBLE_EQ(nudged(out), 10.0);

    out.clear();
    for (int i = 0; i < 12; ++i) { // 12 detents within 22 ms, the other way
        b.feed(step("shuttle_jog", -1, 10.0 + 0.002 * i), out);
    }
    // The 4th counts 1 + 1/3, ..., the 12th 1 + 9/3: 3 + sum over k=4..12 of (k / 3).
    EXPECT_NEAR(nudged(out), -(3.0 + (4 + 5 + 6 + 7 + 8 + 9 + 10 + 11 + 12) / 3.0), 1e-9);

    // A pause longer than the window: back to fine steps.
    out.clear();
    b.feed(step("shuttle_jog", -1, 11.0), out);
    EXPECT_DOUBLE_EQ(nudged(out), -1.0);
}

TEST(ControlBindings, RingRepeatsAtARateByPositionAndStopsAtRest) {
    EXPECT_DOUBLE_EQ(input::ringRepeatsPerSecond(1.0), 20.0);
    EXPECT_DOUBLE_EQ(input::ringRepeatsPerSecond(-0.5), 10.0);
    EXPECT_EQ(input::ringRepeatsPerSecond(0.0), 0.0);

    ControlBindings b = defaults();
    std::vector<Action> out;
    b.feed(ring("shuttle_ring", 0.5, 0.0), out); // one at once, then 10 a second
    EXPECT_DOUBLE_EQ(nudged(out), 10.0);         // coarse: 10 fine steps each
    for (int frame = 1; frame <= 30; ++frame) {  // a second of 30 Hz frames
        b.tick(frame / 30.0, out);
    }
    EXPECT_DOUBLE_EQ(nudged(out), 10.0 * 11); // the first and ten more
    EXPECT_TRUE(b.repeating());

    out.clear();
    b.feed(ring("shuttle_ring", -1.0, 1.0), out); // the other end stop: 20 a second
    for (int frame = 31; frame <= 60; ++frame) {
        b.tick(frame / 30.0, out);
    }
    EXPECT_NEAR(nudged(out), -10.0 * 20, 10.0 * 1);

    out.clear();
    b.feed(ring("shuttle_ring", 0.0, 2.0), out); // springs back: nothing more
    for (int frame = 61; frame <= 120; ++frame) {
        b.tick(frame / 30.0, out);
    }
    EXPECT_TRUE(out.empty());
    EXPECT_FALSE(b.repeating());
}

TEST(ControlBindings, ALongFrameDoesNotBurst) {
    ControlBindings b = defaults();
    std::vector<Action> out;
    b.feed(ring("shuttle_ring", 1.0, 0.0), out);
    out.clear();
    b.tick(10.0, out); // ten seconds without a frame
    EXPECT_LE(out.size(), 5U);
}

TEST(ControlBindings, HoldBindingRunsWhileHeld) {
    ControlBindings b = defaults();
    std::vector<Action> out;
    b.feed(press("pedal", 0.0), out);
    ASSERT_EQ(out.size(), 1U);
    EXPECT_TRUE(std::holds_alternative<model::Run>(out[0]));
    b.feed(release("pedal", 2.0), out);
    ASSERT_EQ(out.size(), 2U);
    EXPECT_TRUE(std::holds_alternative<model::Pause>(out[1]));
    // A plain button does nothing on release.
    out.clear();
    b.feed(press("powermate_press", 3.0), out);
    b.feed(release("powermate_press", 3.1), out);
    ASSERT_EQ(out.size(), 1U);
    EXPECT_TRUE(std::holds_alternative<model::ToggleRun>(out[0]));
}

TEST(ControlBindings, ButtonsOfTheIssuesMapping) {
    ControlBindings b = defaults();
    std::vector<Action> out;
    b.feed(press("shuttle_button1", 0.0), out); // the ShuttleXpress's leftmost
    b.feed(press("shuttle_button2", 0.0), out);
    b.feed(press("shuttle_button5", 0.0), out);
    b.feed(step("powermate_turn", 2, 0.0), out);
    ASSERT_EQ(out.size(), 4U);
    EXPECT_EQ(std::get<model::CycleParam>(out[0]).delta, 1);
    EXPECT_TRUE(std::holds_alternative<model::Undo>(out[1]));
    EXPECT_TRUE(std::holds_alternative<model::Export>(out[2]));
    const auto& radius = std::get<model::NudgeParam>(out[3]);
    EXPECT_EQ(radius.param, model::Param::Radius);
    EXPECT_DOUBLE_EQ(radius.steps, 2.0);
}

TEST(ControlBindings, UnboundControlsAreIgnored) {
    ControlBindings b = defaults();
    std::vector<Action> out;
    b.feed(step("trackball_x", 5, 0.0), out);
    b.feed(ring("trackball_ring", 1.0, 0.0), out);
    b.feed(press("shuttle_button15", 0.0), out);
    b.feed(release("shuttle_button15", 0.0), out);
    // A button name in the knobs' table is not a knob, and the other way round.
    b.feed(step("pedal", 1, 0.0), out);
    b.feed(press("shuttle_jog", 0.0), out);
    b.tick(5.0, out);
    EXPECT_TRUE(out.empty());
    EXPECT_FALSE(b.bound("trackball_x"));
    EXPECT_TRUE(b.bound("shuttle_jog"));
    EXPECT_EQ(b.actionName("pedal"), "run / pause");
}

// Two devices on the selected parameter: the jog turned while the other shuttle's ring is held
// silences the ring until the ring is moved again.
TEST(ControlBindings, LastTouchWins) {
    ControlBindings b = defaults();
    std::vector<Action> out;
    b.feed(ring("shuttlepro_ring", 1.0, 0.0), out);
    b.tick(0.5, out);
    ASSERT_GT(nudged(out), 0.0);
    out.clear();
    b.feed(step("shuttle_jog", -1, 0.5), out);
    for (int frame = 16; frame <= 60; ++frame) {
        b.tick(frame / 30.0, out);
    }
    EXPECT_DOUBLE_EQ(nudged(out), -1.0); // the jog's step alone
    out.clear();
    b.feed(ring("shuttlepro_ring", 0.5, 2.0), out); // touched again: it repeats again
    b.tick(3.0, out);
    EXPECT_GT(nudged(out), 0.0);
}

// Clamping is the workflow's: a knob turned far past T's range lands on its bound and the
// readout (the Status) shows it.
TEST(ControlBindings, AKnobPastTheRangeStopsAtTheBound) {
    Rig rig;
    rig.load();
    ControlBindings b = defaults();
    std::vector<Action> out;
    for (int i = 0; i < 2000; ++i) {
        b.feed(step("shuttle_jog", 5, 0.01 * i), out); // a fast spin: accelerated
    }
    for (const Action& a : out) {
        rig.act(a);
    }
    const workflow::ParamRange& range = rig.status().ranges[0];
    EXPECT_EQ(rig.status().selected, model::Param::T);
    const auto T = [&rig] { return static_cast<double>(rig.status().params.T); };
    EXPECT_LE(T(), range.max);
    EXPECT_GT(T(), range.max - range.fineStep);
    out.clear();
    for (int i = 0; i < 2000; ++i) {
        b.feed(step("shuttle_jog", -5, 100.0 + 0.01 * i), out);
    }
    for (const Action& a : out) {
        rig.act(a);
    }
    EXPECT_GE(T(), range.min);
    EXPECT_LT(T(), range.min + range.fineStep);
}

} // namespace
} // namespace steerseg::test
