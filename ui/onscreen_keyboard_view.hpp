#pragma once

// The on-screen keyboard drawn with Dear ImGui (ui/onscreen_keyboard holds its logic): a
// window across the bottom of an area, over whatever is there, with keys a touch target high
// and as wide as the area allows. Returns the key tapped; the caller presses it.
#include "ui/imgui_layer.hpp"
#include "ui/layout.hpp"
#include "ui/onscreen_keyboard.hpp"

#include <functional>
#include <map>
#include <optional>
#include <string>

namespace steerseg::ui {

struct KeyboardCaption {
    std::string title;   // what the text is for: "Rename 'Liver'"
    std::string problem; // why the last text given was refused, one line ("" = none)
};

struct KeyboardFrame {
    std::optional<Key> pressed;                    // the key tapped this frame
    std::map<std::string, Rect, std::less<>> keys; // where each key was drawn, by keyName
    Rect window;                                   // all the keyboard covers
};

// Inside ImGuiLayer's frame.
KeyboardFrame drawKeyboard(const ImGuiLayer& layer, const OnscreenKeyboard& keyboard,
                           const KeyboardCaption& caption, const Rect& area);

} // namespace steerseg::ui
