#include "ui/structure_editing.hpp"

#include "model/structure.hpp"

#include <algorithm>

namespace steerseg::ui {

namespace {

const workflow::StructureRow* activeRow(const workflow::Status& status) {
    const auto it = std::find_if(status.structures.begin(), status.structures.end(),
                                 [](const workflow::StructureRow& r) { return r.active; });
    return it == status.structures.end() ? nullptr : &*it;
}

} // namespace

void StructureEditing::openRename(const std::string& name) {
    colours_.reset();
    keyboard_.emplace(name, KeyboardOptions{.maxLength = model::kMaxStructureName});
    renaming_ = name;
    handedOver_.reset();
    problem_.clear();
}

void StructureEditing::toggleColours(const std::string& name) {
    if (colours_ == name) {
        colours_.reset();
        return;
    }
    closeRename();
    colours_ = name;
}

std::optional<model::Action> StructureEditing::press(const Key& key) {
    if (!keyboard_) {
        return std::nullopt;
    }
    const std::optional<KeyboardDone> done = keyboard_->press(key);
    if (!done) {
        return std::nullopt;
    }
    if (!done->text || *done->text == renaming_) {
        closeRename();
        return std::nullopt;
    }
    handedOver_ = *done->text;
    return model::EditStructure{model::StructureOp::Rename, renaming_, *done->text,
                                glm::dvec3(0.0)};
}

void StructureEditing::follow(const workflow::Status& status) {
    const workflow::StructureRow* active = activeRow(status);
    const bool editable =
        status.allowed.contains(model::ActionKind::EditStructure) && active != nullptr;
    if (colours_ && (!editable || active->info.name != *colours_)) {
        colours_.reset();
    }
    if (!keyboard_) {
        return;
    }
    if (!editable) {
        closeRename();
        return;
    }
    if (handedOver_ && active->info.name == *handedOver_) {
        closeRename(); // taken
        return;
    }
    if (active->info.name != renaming_) {
        closeRename();
        return;
    }
    if (handedOver_) {
        // Refused: the structure kept its name, and the refusal is the newest message.
        problem_ = status.message.empty() ? "the name '" + *handedOver_ + "' was not taken"
                                          : status.message;
        handedOver_.reset();
    }
}

void StructureEditing::closeRename() {
    keyboard_.reset();
    renaming_.clear();
    handedOver_.reset();
    problem_.clear();
}

} // namespace steerseg::ui
