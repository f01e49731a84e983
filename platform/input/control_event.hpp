#pragma once

// What a knob, ring, button or pedal did, named by control, with no device left in it. The
// kiosk's control bindings map these to workflow actions through the config's
// [bindings.knobs] and [bindings.buttons] tables.
#include <string>

namespace steerseg::platform::input {

struct ControlEvent {
    enum class Kind {
        Step,     // a relative control turned: `steps` detents, + = clockwise
        Position, // an absolute spring-loaded control moved: `position` in -1..1, 0 = rest
        Press,
        Release,
    };
    Kind kind = Kind::Step;
    double time = 0.0;
    // "<device>_<control>" in the config's control-name alphabet (a-z, 0-9, _):
    // "shuttle_jog", "shuttle_ring", "shuttle_button3", "dial_turn", "dial_press",
    // "powermate_turn", "powermate_press"; a GPIO line is its device name alone ("pedal").
    std::string control;
    int steps = 0;
    double position = 0.0;
};

} // namespace steerseg::platform::input
