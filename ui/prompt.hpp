#pragma once

// A question the kiosk puts to the operator over the panel, answered by one of its buttons:
// the start-up offer to resume an unfinished session (docs/kiosk.md). Drawn on top of the
// panel's region, where touches are ImGui's and never reach the views' gestures.
#include "ui/imgui_layer.hpp"
#include "ui/layout.hpp"

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

namespace steerseg::ui {

struct Prompt {
    std::string title; // large: "Resume the last session?"
    std::string text;  // wrapped below it
    std::vector<std::string> choices;
    bool operator==(const Prompt&) const = default;
};

struct PromptFrame {
    std::optional<std::size_t> chosen; // the button pressed this frame
    std::vector<Rect> buttons;         // where each choice was drawn (tests, scripted taps)
};

// Draws the prompt over `panel` (inside ImGuiLayer's frame).
PromptFrame drawPrompt(const ImGuiLayer& layer, const Prompt& prompt, const Rect& panel);

} // namespace steerseg::ui
