#pragma once

// Keys -> the workflow's actions, through the config's [bindings.keys] table. The devices
// issue adds knobs, buttons and pedals beside it; the workflow sees the same actions.
#include "config/kiosk_config.hpp"
#include "model/action.hpp"
#include "platform/input_event.hpp"

#include <optional>
#include <string>

namespace steerseg::input {

// "ctrl+shift+z" for a key-down event with both modifiers: the config's spelling.
std::string bindingKeyName(const platform::InputEvent& event);

class KeyBindings {
  public:
    explicit KeyBindings(config::BindingTable keys);
    // The action a key-down event is bound to; nothing for other events or unbound keys.
    [[nodiscard]] std::optional<model::Action> actionFor(const platform::InputEvent& event) const;

  private:
    config::BindingTable keys_;
};

} // namespace steerseg::input
