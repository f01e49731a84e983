#pragma once

// The panel's rename and recolour of the active structure (docs/structures.md), as plain state:
// which editor is open, the keyboard with the name being typed, and the rename handed to the
// workflow until its status tells how it went. The workflow decides: a name it refuses keeps
// the keyboard open with its reason (Status::message, the refusal's one line).
#include "model/action.hpp"
#include "ui/onscreen_keyboard.hpp"
#include "workflow/status.hpp"

#include <optional>
#include <string>

namespace steerseg::ui {

class StructureEditing {
  public:
    // The Rename button: the keyboard, holding the structure's name.
    void openRename(const std::string& name);
    // The Colour button: the palette's swatches for the structure, or closes them.
    void toggleColours(const std::string& name);
    void closeColours() { colours_.reset(); }

    // A key of the open keyboard. OK with a new name gives the rename to hand to the workflow
    // (kept until follow() sees its outcome); OK with the name unchanged and Cancel close.
    std::optional<model::Action> press(const Key& key);

    // Each frame's status, after the panel's last actions were handled (the kiosk applies
    // them before it draws again): a rename taken closes the keyboard, a refused one keeps it
    // open with the reason; the editors close where structures cannot be edited now (evolving)
    // or when their structure is no longer the active one (selected away, deleted, undone).
    void follow(const workflow::Status& status);

    [[nodiscard]] bool renameOpen() const { return keyboard_.has_value(); }
    [[nodiscard]] bool coloursOpen() const { return colours_.has_value(); }
    [[nodiscard]] const OnscreenKeyboard* keyboard() const {
        return keyboard_ ? &*keyboard_ : nullptr;
    }
    // The name being renamed ("" when the keyboard is closed).
    [[nodiscard]] const std::string& renaming() const { return renaming_; }
    // Why the workflow refused the last name given ("" when it did not).
    [[nodiscard]] const std::string& problem() const { return problem_; }

  private:
    void closeRename();

    std::optional<OnscreenKeyboard> keyboard_;
    std::string renaming_;
    std::optional<std::string> handedOver_; // the new name given to the workflow, outcome unseen
    std::string problem_;
    std::optional<std::string> colours_; // the structure whose swatches are shown
};

} // namespace steerseg::ui
