#include "ui/pacs_form.hpp"

#include <algorithm>

namespace steerseg::ui {

KeyboardOptions keyboardFor(model::SearchField field) {
    switch (field) {
    case model::SearchField::PatientName:
        return {64, "*?^-.,'"}; // "DOE*", "DOE^JANE"
    case model::SearchField::StudyDate:
        return {17, "-"}; // YYYYMMDD-YYYYMMDD
    case model::SearchField::Modality:
        return {16, "\\"};
    case model::SearchField::PatientId:
    case model::SearchField::Accession:
        break;
    }
    return {64, "-_./*?"};
}

void PacsForm::openField(model::SearchField field) {
    keyboard_.emplace(model::keyOf(keys_, field), keyboardFor(field));
    editing_ = field;
}

void PacsForm::press(const Key& key) {
    if (!keyboard_ || !editing_) {
        return;
    }
    const std::optional<KeyboardDone> done = keyboard_->press(key);
    if (!done) {
        return;
    }
    if (done->text) {
        model::keyOf(keys_, *editing_) = *done->text;
    }
    keyboard_.reset();
    editing_.reset();
}

void PacsForm::choosePreset(const std::string& preset) {
    keys_.studyDate = keys_.studyDate == preset ? "" : preset;
}

void PacsForm::follow(const workflow::PacsView& view, bool shown) {
    if (std::find(view.peers.begin(), view.peers.end(), peer_) == view.peers.end()) {
        peer_.clear();
    }
    if (!shown || view.peers.empty()) {
        keyboard_.reset();
        editing_.reset();
        return;
    }
    if (editing_ && std::find(view.fields.begin(), view.fields.end(),
                              model::searchFieldName(*editing_)) == view.fields.end()) {
        keyboard_.reset();
        editing_.reset();
    }
}

} // namespace steerseg::ui
