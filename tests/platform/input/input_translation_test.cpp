// libinput's events, reduced to DeviceEvent, -> InputEvent: touch slots, the screen mapping
// with and without a calibration matrix, key names and modifiers.
#include "platform/input/libinput/input_translation.hpp"
#include "platform/input/libinput/touch_input.hpp"

#include <filesystem>
#include <gtest/gtest.h>
#include <linux/input-event-codes.h>

namespace steerseg::test {
namespace {

namespace in = steerseg::platform::input;
using Kind = steerseg::platform::InputEvent::Kind;
using Type = in::DeviceEvent::Type;

in::DeviceEvent touch(Type type, int slot, double x = 0.0, double y = 0.0) {
    in::DeviceEvent e;
    e.type = type;
    e.slot = slot;
    e.x = x;
    e.y = y;
    e.time = 3.0;
    return e;
}

TEST(InputTranslation, TouchSlotsBecomePointersInScreenPixels) {
    in::InputTranslator t;
    t.setScreen(1920, 1080);
    std::vector<platform::InputEvent> out;
    t.translate(touch(Type::TouchDown, 0, 0.5, 0.25), out);
    t.translate(touch(Type::TouchDown, 1, 0.1, 0.9), out);
    t.translate(touch(Type::TouchMotion, 1, 0.2, 0.8), out);
    t.translate(touch(Type::TouchUp, 0), out);
    t.translate(touch(Type::TouchMotion, 0, 0.3, 0.3), out); // lifted: dropped
    ASSERT_EQ(out.size(), 4U);
    EXPECT_EQ(out[0].kind, Kind::PointerDown);
    EXPECT_EQ(out[0].pointer, 1);
    EXPECT_FLOAT_EQ(out[0].x, 960.0F);
    EXPECT_FLOAT_EQ(out[0].y, 270.0F);
    EXPECT_EQ(out[0].time, 3.0);
    EXPECT_EQ(out[1].pointer, 2);
    EXPECT_EQ(out[2].kind, Kind::PointerMove);
    EXPECT_FLOAT_EQ(out[2].x, 384.0F);
    EXPECT_FLOAT_EQ(out[2].y, 864.0F);
    EXPECT_EQ(out[3].kind, Kind::PointerUp);
    EXPECT_EQ(out[3].pointer, 1);
    EXPECT_FLOAT_EQ(out[3].x, 960.0F) << "an up is where the finger last was";

    out.clear();
    t.translate(touch(Type::TouchCancel, 0), out);
    ASSERT_EQ(out.size(), 1U);
    EXPECT_EQ(out[0].kind, Kind::PointerUp);
    EXPECT_EQ(out[0].pointer, 2);

    out.clear();
    t.translate(touch(Type::TouchDown, in::InputTranslator::kMaxSlots, 0.5, 0.5), out);
    t.translate(touch(Type::TouchDown, -1, 0.5, 0.5), out);
    EXPECT_TRUE(out.empty()) << "slots outside the table are ignored";
    t.translate(touch(Type::TouchDown, 0, 1.2, -0.1), out);
    ASSERT_EQ(out.size(), 1U);
    EXPECT_FLOAT_EQ(out[0].x, 1919.0F) << "clamped to the screen";
    EXPECT_FLOAT_EQ(out[0].y, 0.0F);
}

TEST(InputTranslation, CalibrationFollowsLibinputsConvention) {
    std::string problem;
    // A screen mounted rotated 90 degrees clockwise (libinput's documented example matrix).
    const auto m = in::parseCalibrationMatrix("0 -1 1 1 0 0", problem);
    ASSERT_TRUE(m.has_value()) << problem;
    const auto p = in::applyCalibration(*m, 0.25F, 0.75F);
    EXPECT_FLOAT_EQ(p[0], 0.25F);
    EXPECT_FLOAT_EQ(p[1], 0.25F);

    in::InputTranslator t;
    t.setScreen(1000, 500);
    t.setCalibration(m);
    std::vector<platform::InputEvent> out;
    auto e = touch(Type::TouchDown, 0, 0.25, 0.75);
    t.translate(e, out); // libinput calibrated it already
    e.type = Type::TouchMotion;
    e.calibrateInSoftware = true; // a device libinput cannot calibrate
    t.translate(e, out);
    ASSERT_EQ(out.size(), 2U);
    EXPECT_FLOAT_EQ(out[0].x, 250.0F);
    EXPECT_FLOAT_EQ(out[0].y, 375.0F);
    EXPECT_FLOAT_EQ(out[1].x, 250.0F);
    EXPECT_FLOAT_EQ(out[1].y, 125.0F);

    EXPECT_FALSE(in::parseCalibrationMatrix("1 0 0 0 1", problem).has_value());
    EXPECT_EQ(problem, "calibration matrix '1 0 0 0 1': expected 6 numbers");
    EXPECT_FALSE(in::parseCalibrationMatrix("1 0 0 0 1 0 7", problem).has_value());
    EXPECT_FALSE(in::parseCalibrationMatrix("1 0 x 0 1 0", problem).has_value());
    EXPECT_FALSE(in::parseCalibrationMatrix("1 0 nan 0 1 0", problem).has_value());
}

TEST(InputTranslation, KeysHaveInputEventNamesAndModifiersAreTracked) {
    EXPECT_EQ(in::keyNameForCode(KEY_A), "a");
    EXPECT_EQ(in::keyNameForCode(KEY_Z), "z");
    EXPECT_EQ(in::keyNameForCode(KEY_0), "0");
    EXPECT_EQ(in::keyNameForCode(KEY_KPENTER), "enter");
    EXPECT_EQ(in::keyNameForCode(KEY_EQUAL), "plus");
    EXPECT_EQ(in::keyNameForCode(KEY_F12), "f12");
    EXPECT_EQ(in::keyNameForCode(KEY_ESC), "escape");
    EXPECT_EQ(in::keyNameForCode(KEY_CAPSLOCK), "");

    in::InputTranslator t;
    std::vector<platform::InputEvent> out;
    const auto key = [&](std::uint32_t code, bool pressed) {
        in::DeviceEvent e;
        e.type = Type::Key;
        e.code = code;
        e.pressed = pressed;
        t.translate(e, out);
    };
    key(KEY_LEFTCTRL, true);
    key(KEY_RIGHTSHIFT, true);
    key(KEY_Z, true);
    key(KEY_RIGHTSHIFT, false);
    key(KEY_Z, false);
    key(KEY_LEFTCTRL, false);
    key(KEY_CAPSLOCK, true);
    key(KEY_Y, true);
    ASSERT_EQ(out.size(), 3U) << "modifiers and unnamed keys give no event of their own";
    EXPECT_EQ(out[0].kind, Kind::KeyDown);
    EXPECT_EQ(out[0].key, "z");
    EXPECT_TRUE(out[0].ctrl);
    EXPECT_TRUE(out[0].shift);
    EXPECT_EQ(out[1].kind, Kind::KeyUp);
    EXPECT_TRUE(out[1].ctrl);
    EXPECT_FALSE(out[1].shift);
    EXPECT_FALSE(out[2].ctrl);
}

TEST(InputTranslation, PointerAndWheelArePointerZero) {
    in::InputTranslator t;
    t.setScreen(800, 600);
    std::vector<platform::InputEvent> out;
    in::DeviceEvent e;
    e.type = Type::PointerMotion;
    e.dx = 100.0;
    e.dy = -50.0; // clamped at the top
    t.translate(e, out);
    e.type = Type::PointerButton;
    e.code = BTN_LEFT;
    e.pressed = true;
    t.translate(e, out);
    e.code = BTN_RIGHT;
    t.translate(e, out); // not used
    e.type = Type::PointerMotionAbsolute;
    e.x = 0.5;
    e.y = 0.5;
    t.translate(e, out);
    e.type = Type::ScrollWheel;
    e.scroll = 240.0; // two detents towards the user
    t.translate(e, out);
    e.type = Type::ScrollFinger;
    e.scroll = -15.0;
    t.translate(e, out);
    ASSERT_EQ(out.size(), 5U);
    EXPECT_EQ(out[0].kind, Kind::PointerMove);
    EXPECT_EQ(out[0].pointer, 0);
    EXPECT_FLOAT_EQ(out[0].x, 100.0F);
    EXPECT_FLOAT_EQ(out[0].y, 0.0F);
    EXPECT_EQ(out[1].kind, Kind::PointerDown);
    EXPECT_FLOAT_EQ(out[1].x, 100.0F);
    EXPECT_FLOAT_EQ(out[2].x, 400.0F);
    EXPECT_FLOAT_EQ(out[2].y, 300.0F);
    EXPECT_EQ(out[3].kind, Kind::Wheel);
    EXPECT_FLOAT_EQ(out[3].wheel, -2.0F);
    EXPECT_FLOAT_EQ(out[3].x, 400.0F);
    EXPECT_FLOAT_EQ(out[4].wheel, 1.0F);
}

TEST(TouchInput, PathBackendNamesANodeItCannotUse) {
    in::TouchInputOptions options;
    options.devices = {"/nonexistent-steerseg/event0"};
    std::string problem;
    EXPECT_EQ(in::TouchInput::open(options, problem), nullptr);
    EXPECT_NE(problem.find("/nonexistent-steerseg/event0"), std::string::npos) << problem;
}

TEST(TouchInput, SeatWithoutUdevSaysSo) {
    if (std::filesystem::exists("/run/udev/control")) {
        GTEST_SKIP() << "udev runs here";
    }
    std::string problem;
    EXPECT_EQ(in::TouchInput::open({}, problem), nullptr);
    EXPECT_NE(problem.find("udev is not running"), std::string::npos) << problem;
}

} // namespace
} // namespace steerseg::test
