#pragma once

// A scripted operator session (docs/scripts.md): one step per line, parsed into plain values the
// ScriptPlayer replays frame by frame. Two levels share the format: device-level events
// (touch, keys, wheel) that go through the kiosk's input path as a finger or a keyboard would,
// and named operator actions that go straight to the workflow's action layer. GL-free.
#include "model/action.hpp"
#include "platform/input/raw_record.hpp"
#include "platform/input_event.hpp"

#include <filesystem>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

namespace steerseg::script {

// Every problem of a script, one "SESSION:LINE: problem" line each, joined by '\n'.
class ScriptError : public std::runtime_error {
  public:
    using std::runtime_error::runtime_error;
};

// When a step becomes due. Waits and checks hold the steps after them until they are done.
struct Timing {
    enum Kind {
        Next,  // as soon as the step before is done
        At,    // not before `seconds` after the script's start
        After, // `seconds` after the step before was done
    } kind = Next;
    double seconds = 0.0;
};

// Device level: the events go to the kiosk's input path (gestures, bindings), not the workflow.
struct InputStep {
    std::vector<platform::InputEvent> events; // a tap or a key press is two events
};

// Operator level: one workflow action. LoadScan and Export paths may hold variables ($SCAN).
struct ActionStep {
    model::Action action;
};

// A condition on the workflow's Status: the step that waits for it, or the check that fails.
struct Condition {
    enum Kind {
        State,       // status.state == state
        Loaded,      // a scan is attached: the state has left NoScan and Loading
        Converged,   // status.converged
        Iterations,  // wait: `count` more iterations than when the wait began; expect: >= count
        Seconds,     // wait only: `value` seconds of script clock
        Compare,     // a numeric field against a value
        MessageHas,  // status.message contains `text`
        ExportedHas, // status.exportedPath contains `text`
        Speed,       // status.speedInForce == speed: the speed the engine runs
    } kind = State;
    model::State state = model::State::NoScan;
    model::SpeedKind speed = model::SpeedKind::Threshold;
    std::string field; // Compare: "volume_ml", "iterations", "T", ... (statusFields())
    enum class Op { Less, LessEqual, Greater, GreaterEqual, Equal, NotEqual } op = Op::Equal;
    double value = 0.0;
    long long count = 0;
    std::string text;
};

struct WaitStep {
    Condition condition;
    double timeoutSeconds = 0.0; // script clock; the parser fills in the default
};

struct ExpectStep {
    Condition condition;
};

// A picture of the whole screen after this frame is drawn. A relative path is under $OUT.
struct FrameStep {
    std::string path;
};

// Dice of a mask file (e.g. $EXPORTED) against a reference label file, compared with a bound.
struct DiceStep {
    std::string mask;
    std::string reference;
    int label = -1; // the reference's voxels equal to it; < 0: every non-zero voxel
    Condition::Op op = Condition::Op::GreaterEqual;
    double value = 0.0;
};

// Device level, below the input path: a raw record of an input device (`raw`, a recording line
// without or with its time), or a whole recording file (`replay`), through the kiosk's input
// hub and the device's real decoder (docs/input-devices.md).
struct RawStep {
    std::optional<platform::input::RawRecord> record; // `raw`: stamped with the script clock
    std::string recording;                            // `replay`: the file (may hold $VARs)
};

// The answer to the start-up offer of an unfinished session's autosave (docs/kiosk.md).
struct AutosaveStep {
    bool resume = false; // `autosave resume`; false: `autosave discard`
};
using StepKind = std::variant<InputStep, ActionStep, WaitStep, ExpectStep, FrameStep, DiceStep,
                              RawStep, AutosaveStep>;

struct Step {
    int line = 0;
    std::string text; // the line as written (trimmed, without its comment), for messages
    Timing timing;
    StepKind kind;
};

struct Script {
    std::string name; // how messages name the script (its path as given)
    std::vector<Step> steps;
};

inline constexpr double kDefaultWaitTimeout = 120.0; // seconds of script clock
inline constexpr std::size_t kMaxScriptBytes = 1 << 20;
inline constexpr std::size_t kMaxLineLength = 4096;

// Parses a whole script; throws ScriptError listing every bad line.
Script parseScript(std::string_view text, const std::string& name);
// Reads and parses a file; a missing, unreadable, oversized or binary file is one ScriptError.
Script loadScript(const std::filesystem::path& path);

// The script's names for the workflow's states ("no_scan", "inspect", "review", ...).
std::string_view scriptStateName(model::State state);
std::optional<model::State> scriptStateFromName(std::string_view name);

// The numeric Status fields `expect FIELD OP VALUE` can name, and their value in a status.
const std::vector<std::string_view>& statusFields();

// The variables a script may name: SCAN, DATA, OUT (given before the run), EXPORTED (the path
// of the last export), RECEIVED (the newest complete received series), FOUND (the study UID
// of the last PACS search's first match) and SERIES (the series UID of the last series
// listing's first), known only when the step runs.
const std::vector<std::string_view>& scriptVariables();

} // namespace steerseg::script
