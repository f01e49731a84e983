#pragma once

// The load screen's PACS search form (docs/dicom-network.md "The kiosk's search"), as plain
// state: the query peer chosen (where the site has several), the keys typed so far, the date
// chip chosen, and the on-screen keyboard while a field is typed. The keys stay on the screen until
// changed, so a search can be narrowed; a tap on Search hands the workflow a SearchPacs with them.
#include "model/action.hpp"
#include "ui/onscreen_keyboard.hpp"
#include "workflow/status.hpp"

#include <optional>
#include <string>

namespace steerseg::ui {

class PacsForm {
  public:
    // A field's button: the keyboard, holding what the field has.
    void openField(model::SearchField field);
    // A key of the open keyboard: OK keeps the text in the field, Cancel leaves it as it was;
    // both close the keyboard.
    void press(const Key& key);
    // A date chip: it becomes the date key, or, tapped again, no date at all.
    void choosePreset(const std::string& preset);
    // A peer's button: Search asks it from now on.
    void choosePeer(const std::string& peer) { peer_ = peer; }
    // Each frame: the keyboard closes and the peer is dropped (the first is asked) where the
    // status no longer offers them (the site's config, a screen that left the load screen).
    void follow(const workflow::PacsView& view, bool shown);

    [[nodiscard]] const model::PacsKeys& keys() const { return keys_; }
    [[nodiscard]] const std::string& peer() const { return peer_; } // "" = the first
    [[nodiscard]] bool keyboardOpen() const { return keyboard_.has_value(); }
    [[nodiscard]] const OnscreenKeyboard* keyboard() const {
        return keyboard_ ? &*keyboard_ : nullptr;
    }
    [[nodiscard]] std::optional<model::SearchField> editing() const { return editing_; }

  private:
    model::PacsKeys keys_;
    std::string peer_;
    std::optional<OnscreenKeyboard> keyboard_;
    std::optional<model::SearchField> editing_;
};

// The keys a field's keyboard offers beside letters, digits and space: a name's wildcards
// and DICOM's name separator, an ID's usual punctuation.
KeyboardOptions keyboardFor(model::SearchField field);

} // namespace steerseg::ui
