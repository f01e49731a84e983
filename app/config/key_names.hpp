#pragma once

#include <string_view>

namespace steerseg::config {

// Whether `name` is a key a binding can name: a key name of platform::InputEvent ("a".."z",
// "0".."9", "space", "enter", "escape", "backspace", "tab", "left", "right", "up", "down",
// "pageup", "pagedown", "plus", "minus", "f1".."f12", "delete", "home", "end"), optionally after
// "ctrl+", "shift+" or "ctrl+shift+". config may not include platform/, so this list mirrors
// platform/input_event.hpp's and must change with it.
bool isKeyName(std::string_view name);

// Whether `name` can name a knob, button or pedal: 1 to 32 of a-z, 0-9 and '_'.
bool isControlName(std::string_view name);

} // namespace steerseg::config
