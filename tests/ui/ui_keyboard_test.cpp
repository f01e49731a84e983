// The on-screen keyboard's logic (ui/onscreen_keyboard): what each key does to the text, and
// what OK and Cancel give back.
#include "ui/onscreen_keyboard.hpp"

#include <gtest/gtest.h>
#include <set>
#include <string_view>

namespace steerseg::test {

namespace {

using ui::Key;
using ui::KeyKind;
using ui::OnscreenKeyboard;

Key character(char c) {
    return {KeyKind::Character, c, 1.0};
}
Key key(KeyKind kind) {
    return {kind, 0, 1.0};
}

// Types `text` key by key (letters as their lower-case key); every press must keep it open.
void type(OnscreenKeyboard& k, std::string_view text) {
    for (char c : text) {
        const Key pressed = c == ' ' ? key(KeyKind::Space) : character(c);
        EXPECT_FALSE(k.press(pressed)) << "'" << c << "' ended the typing";
    }
}

} // namespace

TEST(UiKeyboard, TypesLettersDigitsPunctuationAndSpaces) {
    OnscreenKeyboard k("");
    type(k, "gtv-1 (left).");
    EXPECT_EQ(k.text(), "gtv-1 (left).");
}

TEST(UiKeyboard, ShiftCapitalisesTheNextLetterAndCapsLockEveryLetter) {
    OnscreenKeyboard k("");
    k.press(key(KeyKind::Shift));
    EXPECT_TRUE(k.shift());
    EXPECT_EQ(k.label(character('l')), "L");
    type(k, "le");
    EXPECT_EQ(k.text(), "Le") << "shift holds for one letter";
    EXPECT_FALSE(k.shift());
    EXPECT_EQ(k.label(character('l')), "l");
    k.press(key(KeyKind::Shift));
    type(k, "1");
    EXPECT_TRUE(k.shift()) << "a digit leaves shift for the next letter";
    type(k, "f");
    EXPECT_EQ(k.text(), "Le1F");
    k.press(key(KeyKind::CapsLock));
    type(k, "ab");
    EXPECT_EQ(k.text(), "Le1FAB");
    k.press(key(KeyKind::Shift)); // shift under caps lock: one lower-case letter
    type(k, "cd");
    EXPECT_EQ(k.text(), "Le1FABcD");
    k.press(key(KeyKind::CapsLock));
    type(k, "e");
    EXPECT_EQ(k.text(), "Le1FABcDe");
    EXPECT_EQ(k.label(character('-')), "-") << "punctuation has no case";
}

TEST(UiKeyboard, BackspaceAndClearEdit) {
    OnscreenKeyboard k("Liver");
    k.press(key(KeyKind::Backspace));
    k.press(key(KeyKind::Backspace));
    EXPECT_EQ(k.text(), "Liv");
    k.press(key(KeyKind::Clear));
    EXPECT_EQ(k.text(), "");
    k.press(key(KeyKind::Backspace)); // nothing left to take
    EXPECT_EQ(k.text(), "");
}

TEST(UiKeyboard, TypingStopsAtTheMaximumLength) {
    OnscreenKeyboard k("abc", {.maxLength = 5});
    type(k, "defgh");
    EXPECT_EQ(k.text(), "abcde");
    k.press(key(KeyKind::Space));
    EXPECT_EQ(k.text(), "abcde");
    k.press(key(KeyKind::Backspace));
    type(k, "z");
    EXPECT_EQ(k.text(), "abcdz") << "room again after a backspace";
}

TEST(UiKeyboard, OkGivesTheTextAndCancelNothing) {
    OnscreenKeyboard k("Segment 1");
    k.press(key(KeyKind::Clear));
    type(k, "spleen");
    const std::optional<ui::KeyboardDone> ok = k.press(key(KeyKind::Ok));
    ASSERT_TRUE(ok);
    EXPECT_EQ(ok->text, std::optional<std::string>("spleen"));
    EXPECT_EQ(k.text(), "spleen") << "kept for a caller that refuses it";

    OnscreenKeyboard other("Segment 1");
    type(other, "23");
    const std::optional<ui::KeyboardDone> cancel = other.press(key(KeyKind::Cancel));
    ASSERT_TRUE(cancel);
    EXPECT_FALSE(cancel->text) << "cancel gives nothing back";
}

TEST(UiKeyboard, TheRowsHoldEveryKeyOnceAndTheCallersPunctuation) {
    const OnscreenKeyboard k("", {.maxLength = 64, .punctuation = "-*^"});
    std::set<std::string> names;
    std::size_t count = 0;
    for (const std::vector<Key>& row : k.rows()) {
        for (const Key& key : row) {
            names.insert(ui::keyName(key));
            ++count;
            EXPECT_GE(key.width, 1.0);
        }
    }
    EXPECT_EQ(names.size(), count) << "key names are unique";
    for (std::string_view want : {"a", "z", "q", "m", "0", "9", "-", "*", "^", "space", "backspace",
                                  "clear", "shift", "caps", "ok", "cancel"}) {
        EXPECT_TRUE(names.count(std::string(want))) << want;
    }
    EXPECT_EQ(count, 26U + 10U + 3U + 7U);
    EXPECT_FALSE(names.count("(")) << "only the caller's punctuation";
}

} // namespace steerseg::test
