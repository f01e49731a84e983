#include "ui/onscreen_keyboard.hpp"

#include <cctype>
#include <string_view>
#include <utility>

namespace steerseg::ui {

namespace {

Key character(char c) {
    return {KeyKind::Character, c, 1.0};
}

std::vector<Key> characters(std::string_view keys) {
    std::vector<Key> row;
    for (char c : keys) {
        row.push_back(character(c));
    }
    return row;
}

std::vector<std::vector<Key>> layout(const std::string& punctuation) {
    std::vector<std::vector<Key>> rows;
    rows.push_back(characters("1234567890"));
    rows.back().push_back({KeyKind::Backspace, 0, 1.5});
    rows.push_back(characters("qwertyuiop"));
    rows.back().push_back({KeyKind::Clear, 0, 1.5});
    rows.push_back(characters("asdfghjkl"));
    rows.push_back({{KeyKind::Shift, 0, 1.5}});
    for (const Key& k : characters("zxcvbnm")) {
        rows.back().push_back(k);
    }
    rows.back().push_back({KeyKind::CapsLock, 0, 1.5});
    if (!punctuation.empty()) {
        rows.push_back(characters(punctuation));
    }
    rows.push_back({{KeyKind::Cancel, 0, 2.0}, {KeyKind::Space, 0, 5.0}, {KeyKind::Ok, 0, 2.0}});
    return rows;
}

} // namespace

OnscreenKeyboard::OnscreenKeyboard(std::string text, KeyboardOptions options)
    : options_(std::move(options)), text_(std::move(text)), rows_(layout(options_.punctuation)) {}

std::optional<KeyboardDone> OnscreenKeyboard::press(const Key& key) {
    const auto type = [&](char c) {
        if (text_.size() < options_.maxLength) {
            text_.push_back(c);
        }
    };
    switch (key.kind) {
    case KeyKind::Character:
        if (std::isalpha(static_cast<unsigned char>(key.character)) != 0) {
            const auto c = static_cast<unsigned char>(key.character);
            type(static_cast<char>(upper() ? std::toupper(c) : std::tolower(c)));
            shift_ = false;
        } else if (key.character != 0) {
            type(key.character);
        }
        return std::nullopt;
    case KeyKind::Space:
        type(' ');
        return std::nullopt;
    case KeyKind::Backspace:
        if (!text_.empty()) {
            text_.pop_back();
        }
        return std::nullopt;
    case KeyKind::Clear:
        text_.clear();
        return std::nullopt;
    case KeyKind::Shift:
        shift_ = !shift_;
        return std::nullopt;
    case KeyKind::CapsLock:
        capsLock_ = !capsLock_;
        shift_ = false;
        return std::nullopt;
    case KeyKind::Ok:
        return KeyboardDone{text_};
    case KeyKind::Cancel:
        return KeyboardDone{std::nullopt};
    }
    return std::nullopt;
}

std::string OnscreenKeyboard::label(const Key& key) const {
    switch (key.kind) {
    case KeyKind::Character: {
        const auto c = static_cast<unsigned char>(key.character);
        return std::string(1, static_cast<char>(upper() ? std::toupper(c) : c));
    }
    case KeyKind::Space:
        return "Space";
    case KeyKind::Backspace:
        return "<-";
    case KeyKind::Clear:
        return "Clear";
    case KeyKind::Shift:
        return "Shift";
    case KeyKind::CapsLock:
        return "Caps";
    case KeyKind::Ok:
        return "OK";
    case KeyKind::Cancel:
        return "Cancel";
    }
    return "?";
}

std::string keyName(const Key& key) {
    switch (key.kind) {
    case KeyKind::Character:
        return std::string(1, key.character);
    case KeyKind::Space:
        return "space";
    case KeyKind::Backspace:
        return "backspace";
    case KeyKind::Clear:
        return "clear";
    case KeyKind::Shift:
        return "shift";
    case KeyKind::CapsLock:
        return "caps";
    case KeyKind::Ok:
        return "ok";
    case KeyKind::Cancel:
        return "cancel";
    }
    return "?";
}

} // namespace steerseg::ui
