#pragma once

// The console's touchscreen, mouse and keyboard through libinput: the udev backend on a seat,
// or (where udev is not running) the path backend on explicit nodes. Events come out as
// platform::InputEvent in screen pixels (input_translation.hpp).
#include "platform/input/libinput/input_translation.hpp"
#include "platform/input_event.hpp"

#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace steerseg::platform::input {

struct TouchInputOptions {
    std::string seat = "seat0";
    // Non-empty: these nodes through the path backend instead of the seat.
    std::vector<std::string> devices;
    int screenWidth = 1;
    int screenHeight = 1;
    // Overrides udev's LIBINPUT_CALIBRATION_MATRIX on every device that takes one.
    std::optional<CalibrationMatrix> calibration;
};

class TouchInput {
  public:
    // nullptr and a one-line problem naming the failing step.
    static std::unique_ptr<TouchInput> open(const TouchInputOptions& options, std::string& problem);
    ~TouchInput();
    TouchInput(const TouchInput&) = delete;
    TouchInput& operator=(const TouchInput&) = delete;

    [[nodiscard]] int fd() const; // readable when libinput has events
    void setScreen(int width, int height);
    // Appends the pending events without blocking; `now` stamps them.
    void poll(double now, std::vector<InputEvent>& out);
    // Device nodes that could not be opened, calibrations refused: one line each.
    std::vector<std::string> takeProblems();

    struct State;

  private:
    explicit TouchInput(std::unique_ptr<State> state);
    std::unique_ptr<State> state_;
};

} // namespace steerseg::platform::input
