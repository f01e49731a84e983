#pragma once

// A text typed by touch: the console has no physical keyboard. The keys' logic, as plain data
// and state (letters with shift and caps lock, digits, space, the caller's punctuation,
// backspace, clear, OK and cancel); onscreen_keyboard_view draws it with ImGui. Knows nothing
// of what the text is for (a structure's name, a PACS search).
#include <cstddef>
#include <optional>
#include <string>
#include <vector>

namespace steerseg::ui {

enum class KeyKind { Character, Space, Backspace, Clear, Shift, CapsLock, Ok, Cancel };

struct Key {
    KeyKind kind = KeyKind::Character;
    char character = 0; // Character: as typed without shift (a lower-case letter, a digit, ...)
    double width = 1.0; // in widths of a letter's key
    bool operator==(const Key&) const = default;
};

struct KeyboardOptions {
    std::size_t maxLength = 64;           // typing stops there
    std::string punctuation = "-_().,+/"; // the keys beside letters, digits and space
};

// What a press ended: OK gives the text, Cancel nothing (nullopt).
struct KeyboardDone {
    std::optional<std::string> text;
};

class OnscreenKeyboard {
  public:
    // `text`: what the field holds when the keyboard opens (a name to edit).
    explicit OnscreenKeyboard(std::string text, KeyboardOptions options = {});

    // Nothing while typing; OK and Cancel end it (the keyboard keeps its text after OK, for
    // a caller that refuses the text and lets the operator correct it).
    std::optional<KeyboardDone> press(const Key& key);

    [[nodiscard]] const std::string& text() const { return text_; }
    [[nodiscard]] bool shift() const { return shift_; }
    [[nodiscard]] bool capsLock() const { return capsLock_; }
    [[nodiscard]] std::size_t maxLength() const { return options_.maxLength; }
    // The keys in rows, top first: digits, three rows of letters (QWERTY), the punctuation, then
    // cancel, space and OK.
    [[nodiscard]] const std::vector<std::vector<Key>>& rows() const { return rows_; }
    // What a key shows now: "A" while shift or caps is on, "Space", "OK", ...
    [[nodiscard]] std::string label(const Key& key) const;

  private:
    [[nodiscard]] bool upper() const { return shift_ != capsLock_; }

    KeyboardOptions options_;
    std::string text_;
    bool shift_ = false; // the next letter only
    bool capsLock_ = false;
    std::vector<std::vector<Key>> rows_;
};

// A key's name, unique on the keyboard and the same whatever shift shows: "a", "7", "-",
// "space", "backspace", "clear", "shift", "caps", "ok", "cancel" (tests and scripted taps).
std::string keyName(const Key& key);

} // namespace steerseg::ui
