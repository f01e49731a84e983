#pragma once

// The touch panel, drawn with Dear ImGui between ImGuiLayer::beginFrame and endFrame: what
// buildPanelModel offers for the current status, as buttons of at least the touch target's
// size, sliders between -/+ buttons, and large readouts. Returns the actions the operator's
// touches emitted this frame; the caller hands them to the workflow.
#include "ui/imgui_layer.hpp"
#include "ui/layout.hpp"
#include "ui/onscreen_keyboard_view.hpp"
#include "ui/pacs_form.hpp"
#include "ui/panel_model.hpp"
#include "ui/structure_editing.hpp"

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
    // The on-screen keyboard while a structure is being renamed or a search field typed, across the
    // bottom of `area` and over it (after draw, in the same frame); returns the rename its OK
    // gives. Empty and nothing drawn while no keyboard is open.
    std::vector<model::Action> drawKeyboard(const ImGuiLayer& layer, const Rect& area);
    [[nodiscard]] bool keyboardOpen() const {
        return editing_.renameOpen() || pacsForm_.keyboardOpen();
    }
    // Where the keyboard was drawn last frame, and each of its keys by keyName (empty while
    // it is closed).
    [[nodiscard]] const KeyboardFrame& keyboardFrame() const { return keyboard_; }
    [[nodiscard]] const StructureEditing& editing() const { return editing_; }
    [[nodiscard]] const PacsForm& pacsForm() const { return pacsForm_; }

    // Where a widget was drawn last frame, by its label as the model names it ("Run",
    // "Seed##proceed", "+##T" for a parameter's plus button): for tests and scripted taps.
    [[nodiscard]] std::optional<Rect> widgetRect(std::string_view label) const;
    [[nodiscard]] const std::map<std::string, Rect, std::less<>>& widgetRects() const {
        return rects_;
    }

  private:
    // A field or date chip of the search form tapped (Completion::Form), by its label.
    void formTapped(const PacsPanel& pacs, const std::string& label);

    std::map<std::string, Rect, std::less<>> rects_;
    StructureEditing editing_;
    PacsForm pacsForm_;
    KeyboardFrame keyboard_;
};

} // namespace steerseg::ui
