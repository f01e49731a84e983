#pragma once

// What every input decoder must keep, whatever it is fed: a control's Press and Release
// alternate (never two presses without a release), and after reset() nothing is held. A
// broken promise traps, which libFuzzer reports as a crash.
#include "platform/input/control_event.hpp"

#include <map>
#include <string>
#include <vector>

namespace steerseg::fuzz {

class HeldControls {
  public:
    void check(const std::vector<platform::input::ControlEvent>& events) {
        using Kind = platform::input::ControlEvent::Kind;
        for (const auto& e : events) {
            if (e.kind == Kind::Press || e.kind == Kind::Release) {
                bool& held = held_[e.control];
                if (held == (e.kind == Kind::Press)) {
                    __builtin_trap(); // pressed twice, or released while up
                }
                held = e.kind == Kind::Press;
            }
        }
    }
    void checkNothingHeld() const {
        for (const auto& [control, held] : held_) {
            if (held) {
                __builtin_trap(); // reset() left a button down
            }
        }
    }

  private:
    std::map<std::string, bool> held_;
};

} // namespace steerseg::fuzz
