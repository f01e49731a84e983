#include "platform/input/recording.hpp"
#include "script/script_verbs.hpp"
#include "script/script_words.hpp"

namespace steerseg::script::detail {

namespace {

platform::InputEvent pointerEvent(platform::InputEvent::Kind kind, int slot, double x, double y) {
    platform::InputEvent e;
    e.kind = kind;
    e.pointer = slot;
    e.x = static_cast<float>(x);
    e.y = static_cast<float>(y);
    return e;
}

StepKind touch(Words& w) {
    const char* usage = "touch down|move|up SLOT X Y";
    const std::string phase = w.text("down, move or up");
    platform::InputEvent::Kind kind{};
    if (phase == "down") {
        kind = platform::InputEvent::Kind::PointerDown;
    } else if (phase == "move") {
        kind = platform::InputEvent::Kind::PointerMove;
    } else if (phase == "up") {
        kind = platform::InputEvent::Kind::PointerUp;
    } else {
        throw LineError("touch '" + phase + "': give down, move or up (usage: " + usage + ")");
    }
    const int slot = static_cast<int>(w.integer("the finger slot", 0, 15));
    const double x = w.number("x", -kMaxCoordinate, kMaxCoordinate);
    const double y = w.number("y", -kMaxCoordinate, kMaxCoordinate);
    w.finish(usage);
    return InputStep{{pointerEvent(kind, slot, x, y)}};
}

StepKind tap(Words& w) {
    const double x = w.number("x", -kMaxCoordinate, kMaxCoordinate);
    const double y = w.number("y", -kMaxCoordinate, kMaxCoordinate);
    w.finish("tap X Y");
    return InputStep{{pointerEvent(platform::InputEvent::Kind::PointerDown, 0, x, y),
                      pointerEvent(platform::InputEvent::Kind::PointerUp, 0, x, y)}};
}

// "ctrl+shift+z" -> the key and its modifiers.
platform::InputEvent keyEvent(const std::string& chord, platform::InputEvent::Kind kind) {
    platform::InputEvent e;
    e.kind = kind;
    std::string rest = chord;
    for (;;) {
        if (rest.starts_with("ctrl+") && rest.size() > 5) {
            e.ctrl = true;
            rest = rest.substr(5);
        } else if (rest.starts_with("shift+") && rest.size() > 6) {
            e.shift = true;
            rest = rest.substr(6);
        } else {
            break;
        }
    }
    if (!isKeyName(rest)) {
        throw LineError("unknown key '" + chord +
                        "' (a..z, 0..9, space, enter, escape, backspace, tab, left, right, up, "
                        "down, pageup, pagedown, plus, minus, f1..f12, delete, home, end; "
                        "ctrl+ and shift+ before it)");
    }
    e.key = rest;
    return e;
}

Handler key(platform::InputEvent::Kind only, bool both, const char* usage) {
    return [only, both, usage](Words& w) {
        const std::string chord = w.text("a key");
        w.finish(usage);
        InputStep step;
        if (both) {
            step.events.push_back(keyEvent(chord, platform::InputEvent::Kind::KeyDown));
            step.events.push_back(keyEvent(chord, platform::InputEvent::Kind::KeyUp));
        } else {
            step.events.push_back(keyEvent(chord, only));
        }
        return StepKind{step};
    };
}

StepKind wheel(Words& w) {
    const double x = w.number("x", -kMaxCoordinate, kMaxCoordinate);
    const double y = w.number("y", -kMaxCoordinate, kMaxCoordinate);
    const double detents = w.number("the detents", -1000.0, 1000.0);
    w.finish("wheel X Y DETENTS");
    platform::InputEvent e = pointerEvent(platform::InputEvent::Kind::Wheel, 0, x, y);
    e.wheel = static_cast<float>(detents);
    return InputStep{{e}};
}

// `raw [TIME] DEVICE KIND DATA...`: one line of a recording (platform/input/recording.hpp),
// parsed by the recording's own parser. A leading time (a line pasted from a recording) is
// read by parseScript, which spaces a run of timed raw lines as they were recorded.
StepKind raw(Words& w) {
    std::string line;
    while (!w.empty()) {
        line += (line.empty() ? "" : " ") + w.text("a word");
    }
    if (line.empty()) {
        throw LineError("raw: write 'raw DEVICE KIND DATA', a recording line (docs/scripts.md)");
    }
    const bool timed = line.find_first_of("0123456789.") == 0;
    std::string problem;
    auto record = platform::input::parseRecordLine(timed ? line : "0 " + line, problem);
    if (!record) {
        throw LineError("raw: " +
                        (problem.empty() ? std::string("not a recording line") : problem));
    }
    if (!timed) {
        record->time = -1.0; // no time of its own: the step's timing alone
    }
    RawStep step;
    step.record = std::move(*record);
    return step;
}

StepKind replay(Words& w) {
    RawStep step;
    step.recording = pathWord(w, "the recording's path");
    w.finish("replay RECORDING");
    return step;
}

} // namespace

void addDeviceVerbs(VerbTable& table) {
    table.insert({
        {"touch", touch},
        {"tap", tap},
        {"key", key(platform::InputEvent::Kind::KeyDown, true, "key [ctrl+][shift+]NAME")},
        {"key_down", key(platform::InputEvent::Kind::KeyDown, false, "key_down NAME")},
        {"key_up", key(platform::InputEvent::Kind::KeyUp, false, "key_up NAME")},
        {"wheel", wheel},
        // Below the input path: raw device records through the input hub's decoders.
        {"raw", raw},
        {"replay", replay},
    });
}

} // namespace steerseg::script::detail
