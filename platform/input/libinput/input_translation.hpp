#pragma once

// libinput's events, reduced to the fields the kiosk uses, -> platform::InputEvent: touch
// slots, the screen mapping, key names and modifiers. Pure, so it is tested on made-up events;
// touch_input.cpp fills DeviceEvent from libinput.
#include "platform/input_event.hpp"

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace steerseg::platform::input {

// libinput's calibration convention: on coordinates normalised to 0..1,
// x' = m[0] x + m[1] y + m[2],  y' = m[3] x + m[4] y + m[5].
using CalibrationMatrix = std::array<float, 6>;

// Six numbers separated by blanks (the udev property LIBINPUT_CALIBRATION_MATRIX's form);
// nothing and a one-line problem otherwise.
std::optional<CalibrationMatrix> parseCalibrationMatrix(std::string_view text,
                                                        std::string& problem);
std::array<float, 2> applyCalibration(const CalibrationMatrix& m, float x, float y);

// input_event.hpp's name for an evdev KEY_ code; "" for keys the kiosk does not use.
std::string keyNameForCode(std::uint32_t code);

struct DeviceEvent {
    enum class Type {
        TouchDown,
        TouchMotion,
        TouchUp,
        TouchCancel,           // the compositor/kernel took the touches: every finger lifts
        PointerMotion,         // relative: dx, dy in screen pixels
        PointerMotionAbsolute, // x, y normalised 0..1
        PointerButton,         // code = BTN_*
        ScrollWheel,           // scroll: vertical, in 1/120 detents, + = towards the user
        ScrollFinger,          // scroll: vertical touchpad distance, + = towards the user
        Key,                   // code = KEY_*
    };
    Type type = Type::PointerMotion;
    double time = 0.0;
    int slot = 0; // touch: libinput's seat slot
    double x = 0.0;
    double y = 0.0;
    double dx = 0.0;
    double dy = 0.0;
    std::uint32_t code = 0;
    bool pressed = false;
    double scroll = 0.0;
    // The device cannot be calibrated by libinput (it has no calibration support), so the
    // translator applies the configured matrix to x, y itself.
    bool calibrateInSoftware = false;
};

class InputTranslator {
  public:
    static constexpr int kMaxSlots = 10;
    void setScreen(int width, int height);
    void setCalibration(std::optional<CalibrationMatrix> matrix) { calibration_ = matrix; }
    // Appends what the event means; touch slot s is pointer s + 1 (the mouse is pointer 0, as
    // in the window backend), slots beyond kMaxSlots are ignored.
    void translate(const DeviceEvent& event, std::vector<InputEvent>& out);

  private:
    [[nodiscard]] std::array<float, 2> toScreen(const DeviceEvent& event) const;
    InputEvent make(InputEvent::Kind kind, double time) const;
    int width_ = 1;
    int height_ = 1;
    std::optional<CalibrationMatrix> calibration_;
    std::array<bool, kMaxSlots> down_{};
    std::array<std::array<float, 2>, kMaxSlots> last_{};
    float mouseX_ = 0.0F;
    float mouseY_ = 0.0F;
    int ctrlKeys_ = 0;
    int shiftKeys_ = 0;
};

} // namespace steerseg::platform::input
