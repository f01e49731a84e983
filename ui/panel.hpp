#pragma once

// The touch panel, drawn with Dear ImGui between ImGuiLayer::beginFrame and endFrame: what
// buildPanelModel offers for the current status, as buttons of at least the touch target's
// size, sliders between -/+ buttons, and large readouts. Returns the actions the operator's
// touches emitted this frame; the caller hands them to the workflow.
#include "ui/imgui_layer.hpp"
#include "ui/layout.hpp"
#include "ui/panel_model.hpp"

#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace steerseg::ui {

class Panel {
  public:
    std::vector<model::Action> draw(const ImGuiLayer& layer, const workflow::Status& status,
                                    const Rect& rect, const std::vector<std::string>& scans);

    // Where a widget was drawn last frame, by its label as the model names it ("Run",
    // "Seed##proceed", "+##T" for a parameter's plus button): for tests and scripted taps.
    [[nodiscard]] std::optional<Rect> widgetRect(std::string_view label) const;
    [[nodiscard]] const std::map<std::string, Rect, std::less<>>& widgetRects() const {
        return rects_;
    }

  private:
    std::map<std::string, Rect, std::less<>> rects_;
};

} // namespace steerseg::ui
