#include "platform/input/libinput/input_translation.hpp"

#include <algorithm>
#include <cmath>
#include <linux/input-event-codes.h>
#include <sstream>

namespace steerseg::platform::input {

std::optional<CalibrationMatrix> parseCalibrationMatrix(std::string_view text,
                                                        std::string& problem) {
    std::istringstream in{std::string(text)};
    CalibrationMatrix m{};
    for (std::size_t i = 0; i < m.size(); ++i) {
        if (!(in >> m[i]) || !std::isfinite(m[i])) {
            problem = "calibration matrix '" + std::string(text) + "': expected 6 numbers";
            return std::nullopt;
        }
    }
    std::string rest;
    if (in >> rest) {
        problem = "calibration matrix '" + std::string(text) + "': more than 6 numbers";
        return std::nullopt;
    }
    return m;
}

std::array<float, 2> applyCalibration(const CalibrationMatrix& m, float x, float y) {
    return {m[0] * x + m[1] * y + m[2], m[3] * x + m[4] * y + m[5]};
}

std::string keyNameForCode(std::uint32_t code) {
    // KEY_ codes follow the keyboard's rows, not the alphabet.
    static constexpr std::pair<std::uint32_t, const char*> kNames[] = {
        {KEY_A, "a"},
        {KEY_B, "b"},
        {KEY_C, "c"},
        {KEY_D, "d"},
        {KEY_E, "e"},
        {KEY_F, "f"},
        {KEY_G, "g"},
        {KEY_H, "h"},
        {KEY_I, "i"},
        {KEY_J, "j"},
        {KEY_K, "k"},
        {KEY_L, "l"},
        {KEY_M, "m"},
        {KEY_N, "n"},
        {KEY_O, "o"},
        {KEY_P, "p"},
        {KEY_Q, "q"},
        {KEY_R, "r"},
        {KEY_S, "s"},
        {KEY_T, "t"},
        {KEY_U, "u"},
        {KEY_V, "v"},
        {KEY_W, "w"},
        {KEY_X, "x"},
        {KEY_Y, "y"},
        {KEY_Z, "z"},
        {KEY_0, "0"},
        {KEY_1, "1"},
        {KEY_2, "2"},
        {KEY_3, "3"},
        {KEY_4, "4"},
        {KEY_5, "5"},
        {KEY_6, "6"},
        {KEY_7, "7"},
        {KEY_8, "8"},
        {KEY_9, "9"},
        {KEY_SPACE, "space"},
        {KEY_ENTER, "enter"},
        {KEY_KPENTER, "enter"},
        {KEY_ESC, "escape"},
        {KEY_BACKSPACE, "backspace"},
        {KEY_TAB, "tab"},
        {KEY_LEFT, "left"},
        {KEY_RIGHT, "right"},
        {KEY_UP, "up"},
        {KEY_DOWN, "down"},
        {KEY_PAGEUP, "pageup"},
        {KEY_PAGEDOWN, "pagedown"},
        // "+" shares its key with "=" on US and many other layouts; unshifted it means plus.
        {KEY_EQUAL, "plus"},
        {KEY_KPPLUS, "plus"},
        {KEY_MINUS, "minus"},
        {KEY_KPMINUS, "minus"},
        {KEY_DELETE, "delete"},
        {KEY_HOME, "home"},
        {KEY_END, "end"},
        {KEY_F1, "f1"},
        {KEY_F2, "f2"},
        {KEY_F3, "f3"},
        {KEY_F4, "f4"},
        {KEY_F5, "f5"},
        {KEY_F6, "f6"},
        {KEY_F7, "f7"},
        {KEY_F8, "f8"},
        {KEY_F9, "f9"},
        {KEY_F10, "f10"},
        {KEY_F11, "f11"},
        {KEY_F12, "f12"},
    };
    for (const auto& [key, name] : kNames) {
        if (key == code) {
            return name;
        }
    }
    return "";
}

void InputTranslator::setScreen(int width, int height) {
    width_ = std::max(width, 1);
    height_ = std::max(height, 1);
}

std::array<float, 2> InputTranslator::toScreen(const DeviceEvent& event) const {
    std::array<float, 2> p{static_cast<float>(event.x), static_cast<float>(event.y)};
    if (event.calibrateInSoftware && calibration_) {
        p = applyCalibration(*calibration_, p[0], p[1]);
    }
    // A calibrated edge may land just outside; the screen's last pixel is the limit.
    const auto w = static_cast<float>(width_);
    const auto h = static_cast<float>(height_);
    return {std::clamp(p[0] * w, 0.0F, w - 1.0F), std::clamp(p[1] * h, 0.0F, h - 1.0F)};
}

InputEvent InputTranslator::make(InputEvent::Kind kind, double time) const {
    InputEvent e;
    e.kind = kind;
    e.time = time;
    e.ctrl = ctrlKeys_ > 0;
    e.shift = shiftKeys_ > 0;
    return e;
}

void InputTranslator::translate(const DeviceEvent& event, std::vector<InputEvent>& out) {
    using Kind = InputEvent::Kind;
    const bool slotOk = event.slot >= 0 && event.slot < kMaxSlots;
    const auto slot = static_cast<std::size_t>(slotOk ? event.slot : 0);
    switch (event.type) {
    case DeviceEvent::Type::TouchDown:
    case DeviceEvent::Type::TouchMotion: {
        const bool down = event.type == DeviceEvent::Type::TouchDown;
        // A motion of a slot that never went down (it started before we opened) is dropped.
        if (!slotOk || (!down && !down_[slot])) {
            return;
        }
        last_[slot] = toScreen(event);
        InputEvent e =
            make(down && !down_[slot] ? Kind::PointerDown : Kind::PointerMove, event.time);
        down_[slot] = true;
        e.pointer = event.slot + 1;
        e.x = last_[slot][0];
        e.y = last_[slot][1];
        out.push_back(e);
        return;
    }
    case DeviceEvent::Type::TouchUp: {
        if (!slotOk || !down_[slot]) {
            return;
        }
        down_[slot] = false;
        InputEvent e = make(Kind::PointerUp, event.time);
        e.pointer = event.slot + 1;
        e.x = last_[slot][0];
        e.y = last_[slot][1];
        out.push_back(e);
        return;
    }
    case DeviceEvent::Type::TouchCancel:
        for (std::size_t s = 0; s < down_.size(); ++s) {
            if (down_[s]) {
                down_[s] = false;
                InputEvent e = make(Kind::PointerUp, event.time);
                e.pointer = static_cast<int>(s) + 1;
                e.x = last_[s][0];
                e.y = last_[s][1];
                out.push_back(e);
            }
        }
        return;
    case DeviceEvent::Type::PointerMotion:
    case DeviceEvent::Type::PointerMotionAbsolute: {
        if (event.type == DeviceEvent::Type::PointerMotion) {
            mouseX_ = std::clamp(mouseX_ + static_cast<float>(event.dx), 0.0F,
                                 static_cast<float>(width_ - 1));
            mouseY_ = std::clamp(mouseY_ + static_cast<float>(event.dy), 0.0F,
                                 static_cast<float>(height_ - 1));
        } else {
            const auto p = toScreen(event);
            mouseX_ = p[0];
            mouseY_ = p[1];
        }
        InputEvent e = make(Kind::PointerMove, event.time);
        e.x = mouseX_;
        e.y = mouseY_;
        out.push_back(e);
        return;
    }
    case DeviceEvent::Type::PointerButton: {
        if (event.code != BTN_LEFT) {
            return;
        }
        InputEvent e = make(event.pressed ? Kind::PointerDown : Kind::PointerUp, event.time);
        e.x = mouseX_;
        e.y = mouseY_;
        out.push_back(e);
        return;
    }
    case DeviceEvent::Type::ScrollWheel:
    case DeviceEvent::Type::ScrollFinger: {
        // libinput's + is towards the user, input_event.hpp's + away; a finger moving about
        // 15 units is taken as one detent, as libinput's legacy axis did for wheels.
        const double detents = event.type == DeviceEvent::Type::ScrollWheel ? -event.scroll / 120.0
                                                                            : -event.scroll / 15.0;
        if (detents == 0.0) {
            return;
        }
        InputEvent e = make(Kind::Wheel, event.time);
        e.x = mouseX_;
        e.y = mouseY_;
        e.wheel = static_cast<float>(detents);
        out.push_back(e);
        return;
    }
    case DeviceEvent::Type::Key: {
        const int delta = event.pressed ? 1 : -1;
        if (event.code == KEY_LEFTCTRL || event.code == KEY_RIGHTCTRL) {
            ctrlKeys_ = std::max(0, ctrlKeys_ + delta);
            return;
        }
        if (event.code == KEY_LEFTSHIFT || event.code == KEY_RIGHTSHIFT) {
            shiftKeys_ = std::max(0, shiftKeys_ + delta);
            return;
        }
        std::string name = keyNameForCode(event.code);
        if (name.empty()) {
            return;
        }
        InputEvent e = make(event.pressed ? Kind::KeyDown : Kind::KeyUp, event.time);
        e.key = std::move(name);
        out.push_back(std::move(e));
        return;
    }
    }
}

} // namespace steerseg::platform::input
