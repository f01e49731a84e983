#include "input/key_bindings.hpp"

#include <utility>

namespace steerseg::input {

std::string bindingKeyName(const platform::InputEvent& event) {
    std::string name;
    if (event.ctrl) {
        name += "ctrl+";
    }
    if (event.shift) {
        name += "shift+";
    }
    return name + event.key;
}

KeyBindings::KeyBindings(config::BindingTable keys) : keys_(std::move(keys)) {}

std::optional<model::Action> KeyBindings::actionFor(const platform::InputEvent& event) const {
    if (event.kind != platform::InputEvent::Kind::KeyDown || event.key.empty()) {
        return std::nullopt;
    }
    auto it = keys_.find(bindingKeyName(event));
    if (it == keys_.end() && event.shift && !event.ctrl) {
        // "shift+plus" is how some layouts type "+": fall back to the key alone.
        it = keys_.find(event.key);
    }
    if (it == keys_.end()) {
        return std::nullopt;
    }
    return model::bindingAction(it->second.action, it->second.steps);
}

} // namespace steerseg::input
