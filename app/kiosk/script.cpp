// The script parser: a table of verbs, one handler each (the devices issue adds hid, evdev and
// gpio verbs beside touch and key), and the checks every line gets.
#include "kiosk/script.hpp"

#include "kiosk/script_tokens.hpp"
#include "platform/input/recording.hpp"

#include <algorithm>
#include <array>
#include <cstring>
#include <fstream>
#include <functional>
#include <map>
#include <sstream>

namespace steerseg::kiosk {

namespace {

using detail::LineError;
using detail::Words;
using workflow::Action;
using Op = Condition::Op;

constexpr double kMaxSeconds = 1e6;    // a script clock time or a timeout
constexpr double kMaxCoordinate = 1e5; // voxel indices and screen pixels
constexpr double kMaxValue = 1e9;      // parameters, window, field bounds
constexpr int kMaxErrors = 50;
constexpr int kMaxControlLines = 3; // more lines with control characters: a binary file

constexpr std::array<std::string_view, 10> kStateNames = {
    "no_scan", "loading", "inspect",   "seeding", "evolving",
    "paused",  "review",  "exporting", "done",    "error"};

// platform/input_event.hpp's key names.
bool isKeyName(std::string_view key) {
    static const std::vector<std::string_view> kNamed = {
        "space", "enter",  "escape",   "backspace", "tab",   "left",   "right", "up",
        "down",  "pageup", "pagedown", "plus",      "minus", "delete", "home",  "end"};
    if (key.size() == 1) {
        return (key[0] >= 'a' && key[0] <= 'z') || (key[0] >= '0' && key[0] <= '9');
    }
    if (key.size() >= 2 && key.size() <= 3 && key[0] == 'f') {
        const std::string digits(key.substr(1));
        if (digits.find_first_not_of("0123456789") == std::string::npos && digits[0] != '0') {
            const int n = std::stoi(digits);
            return n >= 1 && n <= 12;
        }
        return false;
    }
    return std::find(kNamed.begin(), kNamed.end(), key) != kNamed.end();
}

workflow::State stateWord(Words& words) {
    const std::string name = words.text("a state");
    if (const auto state = scriptStateFromName(name)) {
        return *state;
    }
    std::string known;
    for (const std::string_view s : kStateNames) {
        known += (known.empty() ? "" : ", ") + std::string(s);
    }
    throw LineError("unknown state '" + name + "' (states: " + known + ")");
}

workflow::Param paramWord(Words& words) {
    const std::string name = words.text("a parameter (T, eps, alpha, radius)");
    static const std::map<std::string, workflow::Param, std::less<>> kParams = {
        {"T", workflow::Param::Target},
        {"eps", workflow::Param::Epsilon},
        {"alpha", workflow::Param::Alpha},
        {"radius", workflow::Param::Radius}};
    const auto it = kParams.find(name);
    if (it == kParams.end()) {
        throw LineError("unknown parameter '" + name + "' (T, eps, alpha, radius)");
    }
    return it->second;
}

workflow::SliceAxis axisWord(Words& words) {
    const std::string name = words.text("a slice axis (axial, coronal, sagittal)");
    if (name == "axial") {
        return workflow::SliceAxis::Axial;
    }
    if (name == "coronal") {
        return workflow::SliceAxis::Coronal;
    }
    if (name == "sagittal") {
        return workflow::SliceAxis::Sagittal;
    }
    throw LineError("unknown slice axis '" + name + "' (axial, coronal, sagittal)");
}

Op opWord(Words& words) {
    const std::string op = words.text("a comparison (<, <=, >, >=, ==, !=)");
    static const std::map<std::string, Op, std::less<>> kOps = {
        {"<", Op::Less},          {"<=", Op::LessEqual}, {">", Op::Greater},
        {">=", Op::GreaterEqual}, {"==", Op::Equal},     {"!=", Op::NotEqual}};
    const auto it = kOps.find(op);
    if (it == kOps.end()) {
        throw LineError("'" + op + "' is not a comparison (<, <=, >, >=, ==, !=)");
    }
    return it->second;
}

std::string pathWord(Words& words, const char* what) {
    std::string path = words.text(what);
    if (path.empty()) {
        throw LineError(std::string(what) + " is empty");
    }
    detail::checkVariables(path);
    return path;
}

glm::dvec3 voxelWords(Words& words) {
    const double i = words.number("the voxel's i", -kMaxCoordinate, kMaxCoordinate);
    const double j = words.number("the voxel's j", -kMaxCoordinate, kMaxCoordinate);
    const double k = words.number("the voxel's k", -kMaxCoordinate, kMaxCoordinate);
    return {i, j, k};
}

// --- the verbs ---------------------------------------------------------------------------
using Handler = std::function<StepKind(Words&)>;

StepKind actionStep(Action action) {
    return ActionStep{std::move(action)};
}

template <typename A> Handler plain(const char* usage) {
    return [usage](Words& w) {
        w.finish(usage);
        return actionStep(A{});
    };
}

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

StepKind load(Words& w) {
    std::string path = w.text("a scan path ($SCAN, builtin:sample, ...)");
    if (path.empty()) {
        throw LineError("the scan path is empty");
    }
    detail::checkVariables(path);
    w.finish("load PATH");
    return actionStep(workflow::LoadScan{path});
}

StepKind probe(Words& w) {
    workflow::Probe p;
    p.voxel = voxelWords(w);
    if (!w.empty()) {
        p.radiusMm = w.number("the probe radius (mm)", 0.1, 1000.0);
    }
    w.finish("probe I J K [RADIUS_MM]");
    return actionStep(p);
}

template <typename Sphere> Handler sphere(const char* usage) {
    return [usage](Words& w) {
        Sphere s;
        s.voxel = voxelWords(w);
        if (!w.empty()) {
            s.radius = w.number("the radius (voxels)", 0.1, 10000.0);
        }
        w.finish(usage);
        return actionStep(s);
    };
}

StepKind eraseMode(Words& w) {
    const std::string on = w.text("on or off");
    w.finish("erase_mode on|off");
    if (on != "on" && on != "off") {
        throw LineError("erase_mode '" + on + "': give on or off");
    }
    return actionStep(workflow::SetEraseMode{on == "on"});
}

StepKind autosave(Words& w) {
    const std::string answer = w.text("resume or discard");
    w.finish("autosave resume|discard");
    if (answer != "resume" && answer != "discard") {
        throw LineError("autosave '" + answer + "': give resume or discard");
    }
    return AutosaveStep{answer == "resume"};
}

StepKind set(Words& w) {
    const workflow::Param param = paramWord(w);
    const double value = w.number("the value", -kMaxValue, kMaxValue);
    w.finish("set T|eps|alpha|radius VALUE");
    return actionStep(workflow::SetParam{param, value});
}

StepKind nudge(Words& w) {
    if (w.accept("selected")) {
        const double steps = w.number("the steps", -10000.0, 10000.0);
        w.finish("nudge selected STEPS");
        return actionStep(workflow::NudgeSelected{steps});
    }
    const workflow::Param param = paramWord(w);
    const double steps = w.number("the steps", -10000.0, 10000.0);
    w.finish("nudge T|eps|alpha|radius|selected STEPS");
    return actionStep(workflow::NudgeParam{param, steps});
}

StepKind select(Words& w) {
    const workflow::Param param = paramWord(w);
    w.finish("select T|eps|alpha|radius");
    return actionStep(workflow::SelectParam{param});
}

StepKind cycle(Words& w) {
    int delta = 1;
    if (!w.empty()) {
        delta = static_cast<int>(w.integer("the step", -10, 10));
    }
    w.finish("cycle [STEP]");
    return actionStep(workflow::CycleParam{delta});
}

StepKind preset(Words& w) {
    std::string name = w.text("a preset name");
    w.finish("preset NAME (quote a name with blanks)");
    if (name.empty()) {
        throw LineError("the preset name is empty");
    }
    return actionStep(workflow::ApplyPreset{name});
}

StepKind window(Words& w) {
    const double level = w.number("the level", -kMaxValue, kMaxValue);
    const double width = w.number("the width", 1e-6, kMaxValue);
    w.finish("window LEVEL WIDTH");
    return actionStep(workflow::SetWindow{level, width});
}

StepKind rotate(Words& w) {
    const double yaw = w.number("the yaw (degrees)", -3600.0, 3600.0);
    const double pitch = w.number("the pitch (degrees)", -3600.0, 3600.0);
    w.finish("rotate YAW PITCH");
    return actionStep(workflow::RotateView{yaw, pitch});
}

StepKind zoom(Words& w) {
    const double factor = w.number("the zoom factor", 1e-3, 1e3);
    w.finish("zoom FACTOR");
    return actionStep(workflow::ZoomView{factor});
}

StepKind page(Words& w) {
    const workflow::SliceAxis axis = axisWord(w);
    const int delta = static_cast<int>(w.integer("the slices", -100000, 100000));
    w.finish("page AXIS SLICES");
    return actionStep(workflow::PageSlice{axis, delta});
}

StepKind slice(Words& w) {
    const workflow::SliceAxis axis = axisWord(w);
    const int index = static_cast<int>(w.integer("the slice index", -1, 100000));
    w.finish("slice AXIS INDEX");
    return actionStep(workflow::SetSlice{axis, index});
}

StepKind show(Words& w) {
    const workflow::SliceAxis first = axisWord(w);
    const workflow::SliceAxis second = axisWord(w);
    w.finish("show AXIS AXIS");
    return actionStep(workflow::ShowSlices{first, second});
}

StepKind exportMask(Words& w) {
    std::string path;
    if (!w.empty()) {
        path = pathWord(w, "the export path");
    }
    w.finish("export [PATH]");
    return actionStep(workflow::Export{path});
}

StepKind frame(Words& w) {
    std::string path = pathWord(w, "the frame's path (.png)");
    w.finish("frame PATH.png");
    if (!path.ends_with(".png")) {
        throw LineError("frame '" + path + "': the file name must end in .png");
    }
    return FrameStep{path};
}

double timeoutWords(Words& w) {
    if (w.accept("timeout")) {
        return w.number("the timeout (seconds)", 0.0, kMaxSeconds);
    }
    return kDefaultWaitTimeout;
}

bool isStatusField(const std::string& word) {
    const auto& fields = statusFields();
    return std::find(fields.begin(), fields.end(), word) != fields.end();
}

std::string knownFields() {
    std::string known;
    for (const std::string_view f : statusFields()) {
        known += (known.empty() ? "" : ", ") + std::string(f);
    }
    return known;
}

// FIELD OP VALUE after the field's name, as `expect` and `wait until` share it.
void fieldComparison(Words& w, const std::string& field, Condition& c) {
    c.kind = Condition::Compare;
    c.field = field;
    c.op = opWord(w);
    c.value = w.number("the value", -kMaxValue, kMaxValue);
}

StepKind wait(Words& w) {
    const char* usage =
        "wait converged|loaded|state NAME|iterations N|until FIELD OP VALUE|seconds S [timeout S]";
    const std::string what = w.text("what to wait for (converged, loaded, state, iterations, "
                                    "until, seconds)");
    WaitStep step;
    if (what == "converged") {
        step.condition.kind = Condition::Converged;
    } else if (what == "loaded") {
        step.condition.kind = Condition::Loaded;
    } else if (what == "state") {
        step.condition.kind = Condition::State;
        step.condition.state = stateWord(w);
    } else if (what == "iterations") {
        step.condition.kind = Condition::Iterations;
        step.condition.count = w.integer("the iterations", 1, 100000000);
    } else if (what == "until") {
        // A field reaching a value, whatever changes it: input from outside the script (a
        // device, an X server's injected events) as well as the script's own steps.
        const std::string field = w.text("the field to wait for");
        if (!isStatusField(field)) {
            throw LineError("wait until '" + field + "': not a field (" + knownFields() + ")");
        }
        fieldComparison(w, field, step.condition);
    } else if (what == "seconds") {
        step.condition.kind = Condition::Seconds;
        step.condition.value = w.number("the seconds", 0.0, kMaxSeconds);
        w.finish("wait seconds S");
        return step;
    } else {
        throw LineError("wait '" + what + "': not a condition (usage: " + usage + ")");
    }
    step.timeoutSeconds = timeoutWords(w);
    w.finish(usage);
    return step;
}

StepKind expect(Words& w) {
    const char* usage = "expect state NAME | loaded | converged | FIELD OP VALUE | message "
                        "contains TEXT | exported contains TEXT";
    const std::string what = w.text("what to check");
    ExpectStep step;
    Condition& c = step.condition;
    if (what == "state") {
        c.kind = Condition::State;
        c.state = stateWord(w);
    } else if (what == "loaded") {
        c.kind = Condition::Loaded;
    } else if (what == "converged" && w.empty()) {
        c.kind = Condition::Converged;
    } else if (what == "message" || what == "exported") {
        c.kind = what == "message" ? Condition::MessageHas : Condition::ExportedHas;
        if (!w.accept("contains")) {
            throw LineError("expect " + what + ": write 'expect " + what + " contains TEXT'");
        }
        c.text = w.text("the text");
    } else {
        if (!isStatusField(what)) {
            throw LineError("expect '" + what +
                            "': not a check (state, loaded, converged, "
                            "message, exported, or a field: " +
                            knownFields() + ")");
        }
        fieldComparison(w, what, c);
    }
    w.finish(usage);
    return step;
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

StepKind dice(Words& w) {
    const char* usage = "dice MASK REFERENCE [label N] OP VALUE";
    DiceStep step;
    step.mask = pathWord(w, "the mask's path");
    step.reference = pathWord(w, "the reference's path");
    if (w.accept("label")) {
        step.label = static_cast<int>(w.integer("the label", 0, 65535));
    }
    step.op = opWord(w);
    step.value = w.number("the Dice bound", 0.0, 1.0);
    w.finish(usage);
    return step;
}

const std::map<std::string, Handler, std::less<>>& verbs() {
    static const std::map<std::string, Handler, std::less<>> kVerbs = {
        // device level
        {"touch", touch},
        {"tap", tap},
        {"key", key(platform::InputEvent::Kind::KeyDown, true, "key [ctrl+][shift+]NAME")},
        {"key_down", key(platform::InputEvent::Kind::KeyDown, false, "key_down NAME")},
        {"key_up", key(platform::InputEvent::Kind::KeyUp, false, "key_up NAME")},
        {"wheel", wheel},
        // operator level
        {"load", load},
        {"probe", probe},
        {"seed", sphere<workflow::AddSeed>("seed I J K [RADIUS_VOXELS]")},
        {"erase", sphere<workflow::Erase>("erase I J K [RADIUS_VOXELS]")},
        {"erase_mode", eraseMode},
        {"set", set},
        {"nudge", nudge},
        {"select", select},
        {"cycle", cycle},
        {"preset", preset},
        {"window", window},
        {"run", plain<workflow::Run>("run")},
        {"pause", plain<workflow::Pause>("pause")},
        {"toggle", plain<workflow::ToggleRun>("toggle")},
        {"finish", plain<workflow::Finish>("finish")},
        {"resume", plain<workflow::Resume>("resume")},
        {"undo", plain<workflow::Undo>("undo")},
        {"redo", plain<workflow::Redo>("redo")},
        {"restart", plain<workflow::Restart>("restart")},
        {"proceed", plain<workflow::Proceed>("proceed")},
        {"back", plain<workflow::Back>("back")},
        {"dismiss", plain<workflow::Dismiss>("dismiss")},
        {"quit", plain<workflow::Quit>("quit")},
        {"rotate", rotate},
        {"zoom", zoom},
        {"page", page},
        {"slice", slice},
        {"show", show},
        {"export", exportMask},
        {"frame", frame},
        {"autosave", autosave},
        // waits and checks
        {"wait", wait},
        {"expect", expect},
        {"dice", dice},
        // Below the input path: raw device records through the input hub's decoders.
        {"raw", raw},
        {"replay", replay},
    };
    return kVerbs;
}

std::string trimmed(std::string_view line) {
    const std::size_t begin = line.find_first_not_of(" \t");
    if (begin == std::string_view::npos) {
        return {};
    }
    const std::size_t end = line.find_last_not_of(" \t");
    return std::string(line.substr(begin, end - begin + 1));
}

// Parses one line; nullopt for a blank or comment line.
std::optional<Step> parseLine(std::string_view line, int number, double& lastAt) {
    std::vector<std::string> words = detail::splitWords(line);
    if (words.empty()) {
        return std::nullopt;
    }
    Step step;
    step.line = number;
    step.text = trimmed(detail::withoutComment(line));
    std::size_t first = 0;
    if (words[0] == "at" || words[0] == "after") {
        Words timing(words, 1);
        const double seconds = timing.number(
            words[0] == "at" ? "the time after 'at'" : "the delay after 'after'", 0.0, kMaxSeconds);
        step.timing = {words[0] == "at" ? Timing::At : Timing::After, seconds};
        if (step.timing.kind == Timing::At) {
            if (seconds < lastAt) {
                char text[128];
                std::snprintf(text, sizeof text,
                              "at %g goes back in time (an earlier step is at %g)", seconds,
                              lastAt);
                throw LineError(text);
            }
            lastAt = seconds;
        }
        first = 2;
        if (words.size() <= first) {
            throw LineError("'" + words[0] + " " + words[1] + "' names no step after the time");
        }
    }
    const auto& table = verbs();
    const auto it = table.find(words[first]);
    if (it == table.end()) {
        std::string verb = words[first].substr(0, 40);
        throw LineError("unknown step '" + verb + "' (docs/scripts.md lists the steps)");
    }
    Words rest(std::move(words), first + 1);
    step.kind = it->second(rest);
    return step;
}

// A control character other than a tab, or a carriage return ending a line.
bool isControl(char c) {
    const auto u = static_cast<unsigned char>(c);
    return (u < 0x20 && c != '\t' && c != '\n' && c != '\r') || u == 0x7F;
}

// Lines of `text` holding a control character, and where the first one is: a stray character in
// a text file is one line's problem, a file full of them is not a script at all.
struct ControlLines {
    int lines = 0;
    int firstLine = 0;
    char first = 0;
};

ControlLines controlLines(std::string_view text) {
    ControlLines found;
    int line = 1;
    bool counted = false;
    for (const char c : text) {
        if (c == '\n') {
            ++line;
            counted = false;
        } else if (isControl(c) && !counted) {
            counted = true;
            if (found.lines++ == 0) {
                found.firstLine = line;
                found.first = c;
            }
        }
    }
    return found;
}

// Raw lines pasted from a recording keep their spacing: a timed raw line without its own `at` or
// `after` comes that long after the timed raw line before it (the first of a run at once).
// A replay's relative path is the script's folder's, like the lines it stands for.
void spaceRawLines(Step& step, double& lastRaw, const std::string& scriptName) {
    auto* raw = std::get_if<RawStep>(&step.kind);
    if (raw == nullptr) {
        lastRaw = -1.0;
        return;
    }
    if (!raw->record) {
        lastRaw = -1.0;
        const std::filesystem::path path(raw->recording);
        if (path.is_relative() && !raw->recording.starts_with('$')) {
            raw->recording = (std::filesystem::path(scriptName).parent_path() / path).string();
        }
        return;
    }
    const double time = raw->record->time;
    if (time < 0.0) {
        lastRaw = -1.0;
        return;
    }
    if (step.timing.kind == Timing::Next && lastRaw >= 0.0 && time >= lastRaw) {
        step.timing = {Timing::After, time - lastRaw};
    }
    lastRaw = time;
}

} // namespace

Script parseScript(std::string_view text, const std::string& name) {
    if (text.size() > kMaxScriptBytes) {
        throw ScriptError(name + ": the script is " + std::to_string(text.size()) +
                          " bytes; at most " + std::to_string(kMaxScriptBytes));
    }
    if (const std::size_t nul = text.find('\0'); nul != std::string_view::npos) {
        throw ScriptError(name + ": not a text file (a NUL byte at offset " + std::to_string(nul) +
                          ")");
    }
    if (const ControlLines control = controlLines(text); control.lines > kMaxControlLines) {
        char code[8];
        std::snprintf(code, sizeof code, "0x%02X",
                      static_cast<unsigned>(static_cast<unsigned char>(control.first)));
        throw ScriptError(name + ": not a text file (control characters on " +
                          std::to_string(control.lines) + " lines, the first " + code +
                          " on line " + std::to_string(control.firstLine) + ")");
    }
    Script script;
    script.name = name;
    std::vector<std::string> errors;
    double lastAt = 0.0;
    double lastRaw = -1.0; // the time of the raw line just before, < 0 when there was none
    int number = 0;
    std::size_t pos = 0;
    while (pos < text.size() && static_cast<int>(errors.size()) < kMaxErrors) {
        ++number;
        std::size_t end = text.find('\n', pos);
        if (end == std::string_view::npos) {
            end = text.size();
        }
        std::string_view line = text.substr(pos, end - pos);
        pos = end + 1;
        if (line.ends_with('\r')) {
            line.remove_suffix(1);
        }
        const std::string where = name + ":" + std::to_string(number) + ": ";
        if (line.size() > kMaxLineLength) {
            errors.push_back(where + "the line is " + std::to_string(line.size()) +
                             " characters long; at most " + std::to_string(kMaxLineLength));
            continue;
        }
        const auto control = std::find_if(line.begin(), line.end(), [](char c) {
            const auto u = static_cast<unsigned char>(c);
            return (u < 0x20 && c != '\t') || u == 0x7F;
        });
        if (control != line.end()) {
            char code[8];
            std::snprintf(code, sizeof code, "0x%02X",
                          static_cast<unsigned>(static_cast<unsigned char>(*control)));
            errors.push_back(where + "a control character (" + code +
                             ") in the line; is this a text file?");
            continue;
        }
        try {
            if (auto step = parseLine(line, number, lastAt)) {
                spaceRawLines(*step, lastRaw, name);
                script.steps.push_back(std::move(*step));
            }
        } catch (const LineError& e) {
            errors.push_back(where + e.what());
        }
    }
    if (static_cast<int>(errors.size()) >= kMaxErrors && pos < text.size()) {
        errors.push_back(name + ": more errors after line " + std::to_string(number) +
                         " not listed");
    }
    if (!errors.empty()) {
        std::string all;
        for (const std::string& e : errors) {
            all += (all.empty() ? "" : "\n") + e;
        }
        throw ScriptError(all);
    }
    if (script.steps.empty()) {
        throw ScriptError(name + ": the script has no steps");
    }
    return script;
}

Script loadScript(const std::filesystem::path& path) {
    const std::string name = path.string();
    std::error_code ec;
    const auto status = std::filesystem::status(path, ec);
    if (ec || !std::filesystem::exists(status)) {
        throw ScriptError(name + ": no such script file");
    }
    if (std::filesystem::is_directory(status)) {
        throw ScriptError(name + ": is a folder, not a script file");
    }
    std::ifstream in(path, std::ios::binary);
    if (!in) {
        throw ScriptError(name + ": cannot open the script (" + std::strerror(errno) + ")");
    }
    std::string text;
    text.resize(kMaxScriptBytes + 1);
    in.read(text.data(), static_cast<std::streamsize>(text.size()));
    if (in.bad()) {
        throw ScriptError(name + ": cannot read the script");
    }
    text.resize(static_cast<std::size_t>(in.gcount()));
    if (text.size() > kMaxScriptBytes) {
        throw ScriptError(name + ": the script is larger than " + std::to_string(kMaxScriptBytes) +
                          " bytes");
    }
    return parseScript(text, name);
}

std::string_view scriptStateName(workflow::State state) {
    const auto n = static_cast<std::size_t>(state);
    return n < kStateNames.size() ? kStateNames[n] : std::string_view("unknown");
}

std::optional<workflow::State> scriptStateFromName(std::string_view name) {
    for (std::size_t n = 0; n < kStateNames.size(); ++n) {
        if (kStateNames[n] == name) {
            return static_cast<workflow::State>(n);
        }
    }
    return std::nullopt;
}

const std::vector<std::string_view>& scriptVariables() {
    static const std::vector<std::string_view> kNames = {"SCAN", "DATA", "OUT", "EXPORTED"};
    return kNames;
}

} // namespace steerseg::kiosk
