#include "ui/gestures.hpp"

#include <cmath>
#include <gtest/gtest.h>
#include <limits>

namespace steerseg::test {

using Kind = platform::InputEvent::Kind;
using GK = ui::Gesture::Kind;

namespace {

platform::InputEvent ev(Kind kind, double t, float x, float y, int pointer = 0) {
    platform::InputEvent e;
    e.kind = kind;
    e.time = t;
    e.x = x;
    e.y = y;
    e.pointer = pointer;
    return e;
}

ui::GestureConfig config() {
    ui::GestureConfig c;
    c.slopPx = 8.0;
    c.longPressS = 0.6;
    return c;
}

} // namespace

TEST(UiGestures, ConfigFromMillimetres) {
    const ui::GestureConfig c = ui::gestureConfig(254.0, 2.0, 500.0);
    EXPECT_NEAR(c.slopPx, 20.0, 1e-9);
    EXPECT_NEAR(c.longPressS, 0.5, 1e-12);
    const ui::GestureConfig bad = ui::gestureConfig(std::nan(""), -1.0, 0.0);
    EXPECT_NEAR(bad.slopPx, 2.0 * 96.0 / 25.4, 1e-9);
    EXPECT_GT(bad.longPressS, 0.0);
}

TEST(UiGestures, TapWithinSlop) {
    ui::GestureRecognizer r(config());
    EXPECT_TRUE(r.feed(ev(Kind::PointerDown, 1.0, 100, 100)).empty());
    EXPECT_TRUE(r.feed(ev(Kind::PointerMove, 1.05, 104, 103)).empty());
    const auto out = r.feed(ev(Kind::PointerUp, 1.1, 104, 103));
    ASSERT_EQ(out.size(), 1U);
    EXPECT_EQ(out[0].kind, GK::Tap);
    EXPECT_EQ(out[0].position, glm::dvec2(100, 100));
    EXPECT_EQ(r.pointersDown(), 0);
}

TEST(UiGestures, LongPressFiresOnceWhileHeld) {
    ui::GestureRecognizer r(config());
    r.feed(ev(Kind::PointerDown, 0.0, 50, 60));
    EXPECT_TRUE(r.update(0.5).empty());
    const auto fired = r.update(0.61);
    ASSERT_EQ(fired.size(), 1U);
    EXPECT_EQ(fired[0].kind, GK::LongPress);
    EXPECT_EQ(fired[0].position, glm::dvec2(50, 60));
    EXPECT_TRUE(r.update(0.9).empty());
    EXPECT_TRUE(r.feed(ev(Kind::PointerMove, 1.0, 52, 60)).empty());
    EXPECT_TRUE(r.feed(ev(Kind::PointerUp, 1.2, 52, 60)).empty()) << "no tap after a long press";
}

TEST(UiGestures, LongPressDueAtTheNextEventWithoutUpdate) {
    ui::GestureRecognizer r(config());
    r.feed(ev(Kind::PointerDown, 0.0, 50, 60));
    const auto out = r.feed(ev(Kind::PointerUp, 0.8, 50, 60));
    ASSERT_EQ(out.size(), 1U);
    EXPECT_EQ(out[0].kind, GK::LongPress);
}

TEST(UiGestures, DragBeyondSlopReportsDeltas) {
    ui::GestureRecognizer r(config());
    r.feed(ev(Kind::PointerDown, 0.0, 100, 100));
    EXPECT_TRUE(r.feed(ev(Kind::PointerMove, 0.01, 100, 105)).empty());
    auto a = r.feed(ev(Kind::PointerMove, 0.02, 100, 112));
    ASSERT_EQ(a.size(), 1U);
    EXPECT_EQ(a[0].kind, GK::Drag);
    EXPECT_EQ(a[0].start, glm::dvec2(100, 100));
    EXPECT_EQ(a[0].delta, glm::dvec2(0, 12));
    auto b = r.feed(ev(Kind::PointerMove, 0.03, 90, 130));
    ASSERT_EQ(b.size(), 1U);
    EXPECT_EQ(b[0].delta, glm::dvec2(-10, 18));
    EXPECT_EQ(b[0].id, a[0].id);
    EXPECT_TRUE(r.update(5.0).empty()) << "a drag never becomes a long press";
    EXPECT_FALSE(b[0].lifted);
    // Lifting the finger ends the drag (a painted stroke is applied then), where it last was.
    const auto up = r.feed(ev(Kind::PointerUp, 5.1, 90, 130));
    ASSERT_EQ(up.size(), 1U);
    EXPECT_EQ(up[0].kind, GK::Drag);
    EXPECT_TRUE(up[0].lifted);
    EXPECT_EQ(up[0].id, a[0].id);
    EXPECT_EQ(up[0].delta, glm::dvec2(0, 0));
    EXPECT_EQ(up[0].position, glm::dvec2(90, 130));
}

TEST(UiGestures, ADragJoinedByASecondFingerNeverLifts) {
    ui::GestureRecognizer r(config());
    r.feed(ev(Kind::PointerDown, 0.0, 100, 100, 0));
    const auto drag = r.feed(ev(Kind::PointerMove, 0.02, 100, 130, 0));
    ASSERT_EQ(drag.size(), 1U);
    r.feed(ev(Kind::PointerDown, 0.05, 200, 130, 1));
    const auto pinch = r.feed(ev(Kind::PointerMove, 0.06, 100, 150, 0));
    ASSERT_EQ(pinch.size(), 1U);
    EXPECT_EQ(pinch[0].kind, GK::Pinch);
    EXPECT_NE(pinch[0].id, drag[0].id);
    // Two fingers dragging together: the centre's motion, for paging a slice.
    EXPECT_EQ(pinch[0].delta, glm::dvec2(0, 10));
    EXPECT_TRUE(r.feed(ev(Kind::PointerUp, 0.1, 100, 150, 0)).empty());
    EXPECT_TRUE(r.feed(ev(Kind::PointerUp, 0.1, 200, 130, 1)).empty());
}

TEST(UiGestures, PinchReportsScaleAndCentre) {
    ui::GestureRecognizer r(config());
    r.feed(ev(Kind::PointerDown, 0.0, 100, 100, 3));
    r.feed(ev(Kind::PointerDown, 0.01, 200, 100, 5));
    const auto out = r.feed(ev(Kind::PointerMove, 0.02, 300, 100, 5));
    ASSERT_EQ(out.size(), 1U);
    EXPECT_EQ(out[0].kind, GK::Pinch);
    EXPECT_NEAR(out[0].scale, 2.0, 1e-12);
    EXPECT_EQ(out[0].position, glm::dvec2(200, 100));
    EXPECT_EQ(out[0].start, glm::dvec2(150, 100));
    const auto in = r.feed(ev(Kind::PointerMove, 0.03, 200, 100, 3));
    ASSERT_EQ(in.size(), 1U);
    EXPECT_NEAR(in[0].scale, 0.5, 1e-12);
    // The finger left behind neither drags nor taps.
    EXPECT_TRUE(r.feed(ev(Kind::PointerUp, 0.04, 300, 100, 5)).empty());
    EXPECT_TRUE(r.feed(ev(Kind::PointerMove, 0.05, 400, 300, 3)).empty());
    EXPECT_TRUE(r.feed(ev(Kind::PointerUp, 0.06, 400, 300, 3)).empty());
    EXPECT_EQ(r.pointersDown(), 0);
}

TEST(UiGestures, Wheel) {
    ui::GestureRecognizer r(config());
    platform::InputEvent w = ev(Kind::Wheel, 0.0, 10, 20);
    w.wheel = -2.0F;
    const auto out = r.feed(w);
    ASSERT_EQ(out.size(), 1U);
    EXPECT_EQ(out[0].kind, GK::Wheel);
    EXPECT_EQ(out[0].wheel, -2.0);
    EXPECT_EQ(out[0].position, glm::dvec2(10, 20));
    w.wheel = std::numeric_limits<float>::quiet_NaN();
    EXPECT_TRUE(r.feed(w).empty());
    w.wheel = 0.0F;
    EXPECT_TRUE(r.feed(w).empty());
}

TEST(UiGestures, OddSequences) {
    ui::GestureRecognizer r(config());
    EXPECT_TRUE(r.feed(ev(Kind::PointerUp, 0.0, 1, 1)).empty()) << "up without down";
    EXPECT_TRUE(r.feed(ev(Kind::PointerMove, 0.0, 50, 50)).empty()) << "hover";
    EXPECT_TRUE(r.feed(ev(Kind::PointerDown, 0.0, 1, 1, -1)).empty());
    EXPECT_TRUE(r.feed(ev(Kind::PointerDown, 0.0, 1, 1, 99)).empty());
    EXPECT_EQ(r.pointersDown(), 0);
    platform::InputEvent key;
    key.kind = Kind::KeyDown;
    key.key = "space";
    EXPECT_TRUE(r.feed(key).empty());

    // A repeated down keeps the tap.
    r.feed(ev(Kind::PointerDown, 1.0, 10, 10));
    r.feed(ev(Kind::PointerDown, 1.01, 10, 10));
    const auto tap = r.feed(ev(Kind::PointerUp, 1.02, 10, 10));
    ASSERT_EQ(tap.size(), 1U);
    EXPECT_EQ(tap[0].kind, GK::Tap);
}

TEST(UiGestures, TenFingers) {
    ui::GestureRecognizer r(config());
    for (int f = 0; f < 10; ++f) {
        const auto out = r.feed(ev(Kind::PointerDown, 0.01 * f, 30.0F * f, 40, f));
        for (const auto& g : out) {
            EXPECT_NE(g.kind, GK::Tap);
        }
    }
    EXPECT_EQ(r.pointersDown(), 10);
    for (int f = 0; f < 10; ++f) {
        for (const auto& g : r.feed(ev(Kind::PointerMove, 0.2, 30.0F * f + 50, 90, f))) {
            EXPECT_NE(g.kind, GK::Drag);
        }
    }
    EXPECT_TRUE(r.update(3.0).empty());
    for (int f = 9; f >= 0; --f) {
        EXPECT_TRUE(r.feed(ev(Kind::PointerUp, 3.1, 0, 0, f)).empty());
    }
    EXPECT_EQ(r.pointersDown(), 0);
    // And the next touch is an ordinary tap again.
    r.feed(ev(Kind::PointerDown, 4.0, 5, 5, 2));
    const auto out = r.feed(ev(Kind::PointerUp, 4.1, 5, 5, 2));
    ASSERT_EQ(out.size(), 1U);
    EXPECT_EQ(out[0].kind, GK::Tap);
}

TEST(UiGestures, NanCoordinatesIgnored) {
    const float nan = std::numeric_limits<float>::quiet_NaN();
    ui::GestureRecognizer r(config());
    EXPECT_TRUE(r.feed(ev(Kind::PointerDown, 0.0, nan, 5)).empty());
    EXPECT_EQ(r.pointersDown(), 0);
    r.feed(ev(Kind::PointerDown, 0.0, 20, 20));
    EXPECT_TRUE(r.feed(ev(Kind::PointerMove, 0.01, nan, nan)).empty());
    EXPECT_TRUE(
        r.feed(ev(Kind::PointerMove, 0.01, std::numeric_limits<float>::infinity(), 0)).empty());
    const auto out = r.feed(ev(Kind::PointerUp, 0.02, nan, nan));
    ASSERT_EQ(out.size(), 1U);
    EXPECT_EQ(out[0].kind, GK::Tap);
    EXPECT_EQ(out[0].position, glm::dvec2(20, 20));
    EXPECT_EQ(r.pointersDown(), 0);
}

} // namespace steerseg::test
