#include "config/key_names.hpp"

#include <algorithm>
#include <array>

namespace steerseg::config {

namespace {

// platform/input_event.hpp's named keys besides letters, digits and f1..f12.
constexpr std::array<std::string_view, 16> kNamedKeys{
    "space", "enter",  "escape",   "backspace", "tab",   "left",   "right", "up",
    "down",  "pageup", "pagedown", "plus",      "minus", "delete", "home",  "end"};

bool isBareKey(std::string_view name) {
    if (name.size() == 1) {
        const char c = name[0];
        return (c >= 'a' && c <= 'z') || (c >= '0' && c <= '9');
    }
    if (name.size() >= 2 && name.size() <= 3 && name[0] == 'f') {
        const std::string_view digits = name.substr(1);
        if (!std::all_of(digits.begin(), digits.end(),
                         [](char c) { return c >= '0' && c <= '9'; }) ||
            digits[0] == '0') {
            return false;
        }
        const int n =
            digits.size() == 1 ? digits[0] - '0' : (digits[0] - '0') * 10 + digits[1] - '0';
        return n >= 1 && n <= 12;
    }
    return std::find(kNamedKeys.begin(), kNamedKeys.end(), name) != kNamedKeys.end();
}

} // namespace

bool isKeyName(std::string_view name) {
    for (const std::string_view modifier : {"ctrl+", "shift+"}) {
        if (name.starts_with(modifier)) {
            name.remove_prefix(modifier.size());
        }
    }
    return isBareKey(name);
}

bool isControlName(std::string_view name) {
    return !name.empty() && name.size() <= 32 && std::all_of(name.begin(), name.end(), [](char c) {
        return (c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') || c == '_';
    });
}

} // namespace steerseg::config
