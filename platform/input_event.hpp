#pragma once

// Pointer and key events in the form every source delivers them: the window's mouse, keyboard
// and touch, the console's touchscreen, and a script's device-level events. Devices with knobs
// and pedals (the devices issue) decode into bindings, not into these.
#include <string>

namespace steerseg::platform {

struct InputEvent {
    enum class Kind {
        PointerDown, // a finger touches, or the mouse's left button goes down
        PointerMove,
        PointerUp,
        Wheel,   // mouse wheel or a touchpad scroll: `wheel` detents, + = away from the user
        KeyDown, // `key` is a lower-case name: "a".."z", "0".."9", "space", "enter", "escape",
        KeyUp,   // "backspace", "tab", "left", "right", "up", "down", "pageup", "pagedown",
                 // "plus", "minus", "f1".."f12", "delete", "home", "end"
        Quit,    // window closed, display lost, SIGTERM
    };
    Kind kind = Kind::PointerMove;
    double time = 0.0; // seconds, monotonic (steady clock), or the script's clock
    int pointer = 0;   // finger slot; the mouse is pointer 0
    float x = 0.0F;    // framebuffer pixels, origin top left
    float y = 0.0F;
    float wheel = 0.0F;
    std::string key;
    bool ctrl = false;
    bool shift = false;
};

} // namespace steerseg::platform
