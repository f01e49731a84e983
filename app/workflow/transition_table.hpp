#pragma once

// The workflow's rules as data: in which states an action kind is accepted, under which guard,
// which state follows, and the one-line refusal otherwise. Workflow::handle runs it before an
// action's own code, Status::allowed publishes it, and docs/workflow.md prints it
// (transition_markdown.hpp; a unit test keeps the two equal).
#include "model/action.hpp"
#include "workflow/status.hpp"

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <initializer_list>
#include <optional>
#include <span>
#include <string>
#include <string_view>

namespace steerseg::workflow {

inline constexpr std::size_t kStateCount = static_cast<std::size_t>(model::State::Error) + 1;

class StateSet {
  public:
    constexpr StateSet() = default;
    constexpr StateSet(std::initializer_list<model::State> states) {
        for (const model::State s : states) {
            bits_ |= bit(s);
        }
    }
    [[nodiscard]] constexpr bool contains(model::State state) const {
        return (bits_ & bit(state)) != 0;
    }

  private:
    static constexpr std::uint16_t bit(model::State state) {
        return static_cast<std::uint16_t>(1U << static_cast<unsigned>(state));
    }
    std::uint16_t bits_ = 0;
};

// What the workflow knows besides its state that decides whether an action may happen.
struct Facts {
    bool levelSet = false;
    bool unexported = false;
    bool canUndo = false;
    bool canRedo = false;
    bool examples = false;          // classify has an inside or an outside example
    bool auditLost = false;         // the audit log cannot be written now
    bool auditAcknowledged = false; // ... and the operator said to export anyway
    bool box = false;               // the operator's box is set (model::SetBox)
    bool result = false; // the level set, or another structure, has a surface: something to export
};
// The same facts as a status shows them (a status built by hand, a test's).
inline Facts factsOf(const Status& status) {
    return {status.hasLevelSet,
            status.unexported,
            status.canUndo,
            status.canRedo,
            !status.insideExamples.empty() || !status.outsideExamples.empty() ||
                !status.paintedInside.empty() || !status.paintedOutside.empty(),
            !status.auditProblem.empty(),
            status.auditAcknowledged,
            status.box.has_value(),
            status.hasLevelSet ||
                std::any_of(status.structures.begin(), status.structures.end(),
                            [](const StructureRow& r) { return !r.active && !r.empty; })};
}

enum class Guard {
    Always,
    Never,
    LevelSet,
    NoUnexportedWork,
    CanUndo,
    CanRedo,
    Examples,
    Box,
    Result,    // a surface in some structure (Facts::result)
    AuditKept, // the audit log is written, or the operator acknowledged that it cannot be
    AuditLost, // the audit log cannot be written and that is not acknowledged yet
};
std::string_view guardName(Guard guard); // the docs' words: "always", "level set", ...
constexpr bool holds(Guard guard, const Facts& facts) {
    switch (guard) {
    case Guard::Always:
        return true;
    case Guard::Never:
        return false;
    case Guard::LevelSet:
        return facts.levelSet;
    case Guard::NoUnexportedWork:
        return !facts.unexported;
    case Guard::CanUndo:
        return facts.canUndo;
    case Guard::CanRedo:
        return facts.canRedo;
    case Guard::Examples:
        return facts.examples;
    case Guard::Box:
        return facts.box;
    case Guard::Result:
        return facts.result;
    case Guard::AuditKept:
        return !facts.auditLost || facts.auditAcknowledged;
    case Guard::AuditLost:
        return facts.auditLost && !facts.auditAcknowledged;
    }
    return false;
}

struct Rule {
    StateSet states;
    model::ActionKinds actions;
    Guard guard = Guard::Always;
    // nullopt: the state stays, unless the action's own code moves it (`note` says where).
    std::optional<model::State> next;
    std::string_view refusal; // when the guard fails; "{state}" stands for the state's name
    std::string_view note = {};
    // A second condition with its own refusal, checked after the first (export: the audit).
    Guard also = Guard::Always;
    std::string_view alsoRefusal = {};
};

// The refusal of every action kind no rule names in a state.
struct StateDefault {
    model::State state;
    std::string_view refusal;
};

// The table itself, in the docs' order. At most one rule names any (state, action kind), and a
// state without a default has a rule for every kind (workflow_table_test). It lives in this
// header so the screen (which links no workflow code) can ask it.
namespace table {
using K = model::ActionKind;
using S = model::State;

inline constexpr StateSet kAll{S::NoScan, S::Loading, S::Inspect,   S::Seeding, S::Evolving,
                               S::Paused, S::Review,  S::Exporting, S::Done,    S::Error};
inline constexpr StateSet kWithScan{S::Inspect, S::Seeding,   S::Evolving, S::Paused,
                                    S::Review,  S::Exporting, S::Done,     S::Error};
inline constexpr StateSet kSteering{S::Inspect, S::Seeding, S::Evolving, S::Paused};

// Looking around: the view, the knob's selection and the tap's meaning. Also in error, where
// they leave the error's message on screen.
inline constexpr model::ActionKinds kLooking{
    K::RotateView,  K::ZoomView,   K::PageSlice,    K::SetSlice,       K::ShowSlices, K::SetWindow,
    K::SelectParam, K::CycleParam, K::SetEraseMode, K::SetOutsideMode, K::SetBoxMode};
// Parameters and the speed: live in every steering state, evolving included.
inline constexpr model::ActionKinds kSteer{K::Probe,      K::ApplyPreset,   K::SetParam,
                                           K::NudgeParam, K::NudgeSelected, K::SetSpeed,
                                           K::MarkOutside};
constexpr model::ActionKinds with(model::ActionKinds kinds, model::ActionKinds more) {
    kinds.insert(more);
    return kinds;
}
// The same with clear_examples (guarded apart while steering), and the spheres besides: what
// review and done refuse.
inline constexpr model::ActionKinds kSteerAll = with(kSteer, {K::ClearExamples});
inline constexpr model::ActionKinds kExportedRefused =
    with(kSteerAll, {K::AddSeed, K::Erase, K::PaintStroke, K::Correct, K::SetBox, K::ClearBox});

inline constexpr std::string_view kNoLevelSetToRun = "no level set to evolve: add a seed first";
inline constexpr std::string_view kNothingToExport = "nothing to export: add a seed first";
inline constexpr std::string_view kExportNote =
    "then done; a failure goes back to review with the writer's message, the work kept";
inline constexpr std::string_view kAuditLost =
    "the audit log cannot be written: acknowledge (acknowledge_audit) to export without it";

// clang-format off
inline constexpr std::array kRules{
    Rule{{S::NoScan, S::Loading, S::Inspect, S::Seeding, S::Evolving, S::Paused, S::Review, S::Done, S::Error},
         {K::LoadScan}, Guard::NoUnexportedWork, S::Loading,
         "the segmentation is not exported: export or restart first"},
    Rule{kWithScan, kLooking, Guard::Always, std::nullopt, {}},
    Rule{kSteering, kSteer, Guard::Always, std::nullopt, {}},
    Rule{kSteering, {K::ClearExamples}, Guard::Examples, std::nullopt, "no examples to clear"},
    Rule{{S::Review}, kSteerAll, Guard::Never, std::nullopt,
         "go back to steering to change parameters"},
    Rule{{S::Done}, kExportedRefused, Guard::Never, std::nullopt,
         "the result is exported: go back to review, or load the next scan"},
    // The spheres.
    Rule{{S::Inspect}, {K::AddSeed}, Guard::Always, S::Seeding, {}, "the seed is placed"},
    Rule{{S::Seeding, S::Evolving, S::Paused}, {K::AddSeed, K::Erase}, Guard::Always, std::nullopt,
         {}, "evolving: an erase that empties the level set pauses"},
    Rule{{S::Inspect}, {K::Erase}, Guard::Never, std::nullopt, "place a seed before erasing"},
    Rule{{S::Review}, {K::AddSeed, K::Erase, K::PaintStroke, K::Correct, K::SetBox, K::ClearBox},
         Guard::Never, std::nullopt, "go back to steering to edit the surface"},
    Rule{{S::Inspect, S::Seeding, S::Paused}, {K::Correct}, Guard::Always, S::Evolving, {},
         "the first probes and seeds; an erase that leaves nothing stays"},
    Rule{{S::Evolving}, {K::Correct}, Guard::Always, std::nullopt, {}, "from the current surface"},
    // The box: the first one probes and seeds at its centre, a later one moves it.
    Rule{{S::Inspect}, {K::SetBox}, Guard::Always, S::Seeding, {}, "its probe and seed are placed"},
    Rule{{S::Seeding, S::Evolving, S::Paused}, {K::SetBox}, Guard::Always, std::nullopt, {},
         "the surface follows the box"},
    Rule{kSteering, {K::ClearBox}, Guard::Box, std::nullopt, "no box to clear"},
    // A stroke is the brush along a path in the mode it names; its own code refuses what that
    // mode's sphere would (an erase with nothing to erase).
    Rule{kSteering, {K::PaintStroke}, Guard::Always, std::nullopt, {},
         "add from inspect goes to seeding; evolving: an erase that empties the level set pauses"},
    // The run.
    Rule{{S::Seeding, S::Paused}, {K::Run, K::ToggleRun}, Guard::LevelSet, S::Evolving,
         kNoLevelSetToRun},
    Rule{{S::Seeding}, {K::Proceed}, Guard::LevelSet, S::Evolving, kNoLevelSetToRun},
    Rule{{S::Evolving}, {K::Run}, Guard::Always, std::nullopt, {}, "already running"},
    Rule{{S::Evolving}, {K::Pause, K::ToggleRun}, Guard::Always, S::Paused, {}},
    Rule{{S::Paused}, {K::Pause}, Guard::Always, std::nullopt, {}},
    Rule{{S::Inspect}, {K::Run, K::ToggleRun}, Guard::Never, std::nullopt,
         "place a seed before running"},
    Rule{{S::Review}, {K::Run, K::ToggleRun}, Guard::Never, std::nullopt,
         "resume steering before running"},
    Rule{{S::Done}, {K::Run, K::ToggleRun}, Guard::Never, std::nullopt, "nothing to run in {state}"},
    Rule{{S::NoScan, S::Loading, S::Inspect, S::Seeding, S::Review, S::Done}, {K::Pause},
         Guard::Never, std::nullopt, "not running"},
    // Review.
    Rule{{S::Seeding, S::Evolving, S::Paused}, {K::Finish}, Guard::Result, S::Review,
         "nothing to review: add a seed first"},
    Rule{{S::Evolving, S::Paused}, {K::Proceed}, Guard::Result, S::Review,
         "nothing to review: add a seed first"},
    Rule{{S::Review}, {K::Finish}, Guard::Always, std::nullopt, {}},
    // Inspect after a new structure: the others may be finished without it.
    Rule{{S::Inspect}, {K::Finish}, Guard::Result, S::Review, "nothing to finish in {state}"},
    Rule{{S::Done}, {K::Finish}, Guard::Never, std::nullopt, "nothing to finish in {state}"},
    Rule{{S::Review}, {K::Resume, K::Back}, Guard::Always, S::Paused, {}},
    Rule{{S::NoScan, S::Loading, S::Inspect, S::Seeding, S::Evolving, S::Paused, S::Done},
         {K::Resume}, Guard::Never, std::nullopt, "resume goes from review back to steering"},
    // Export.
    Rule{{S::Review, S::Paused}, {K::Export}, Guard::Result, S::Exporting, kNothingToExport,
         kExportNote, Guard::AuditKept, kAuditLost},
    Rule{{S::Review}, {K::Proceed}, Guard::Result, S::Exporting, kNothingToExport, kExportNote,
         Guard::AuditKept, kAuditLost},
    Rule{{S::Inspect, S::Seeding, S::Evolving, S::Done}, {K::Export}, Guard::Never, std::nullopt,
         "export from review (or paused)"},
    // Undo, restart.
    Rule{{S::Inspect, S::Seeding, S::Paused}, {K::Undo}, Guard::CanUndo, std::nullopt,
         "nothing to undo"},
    Rule{{S::Inspect, S::Seeding, S::Paused}, {K::Redo}, Guard::CanRedo, std::nullopt,
         "nothing to redo"},
    Rule{{S::Evolving}, {K::Undo}, Guard::CanUndo, S::Paused, "nothing to undo",
         "the operator sees what came back before it moves again"},
    Rule{{S::Evolving}, {K::Redo}, Guard::CanRedo, S::Paused, "nothing to redo"},
    Rule{{S::Review, S::Done}, {K::Undo, K::Redo}, Guard::Never, std::nullopt,
         "go back to steering to undo"},
    Rule{{S::Inspect, S::Seeding, S::Evolving, S::Paused, S::Review, S::Done}, {K::Restart},
         Guard::LevelSet, S::Seeding, "nothing to restart: the level set is empty",
         "clears the level set; undoable"},
    // The workflow's own steps.
    Rule{{S::Inspect}, {K::Proceed}, Guard::Always, S::Seeding, {}},
    Rule{{S::Done}, {K::Proceed}, Guard::Never, std::nullopt, "done: load the next scan"},
    Rule{{S::Seeding}, {K::Back}, Guard::Always, S::Inspect, {}},
    Rule{{S::Done}, {K::Back}, Guard::Always, S::Review, {}},
    Rule{{S::NoScan, S::Loading, S::Inspect, S::Evolving, S::Paused}, {K::Back}, Guard::Never,
         std::nullopt, "no step back from {state}"},
    // The structures: the action's own code moves the state (model::EditStructure).
    Rule{{S::Inspect, S::Seeding, S::Paused, S::Review, S::Done}, {K::EditStructure}, Guard::Always,
         std::nullopt, {},
         "add goes to inspect; select to paused, or inspect for an empty one; delete of the active one as select"},
    Rule{{S::Evolving}, {K::EditStructure}, Guard::Never, std::nullopt,
         "pause before changing structures"},
    Rule{kAll, {K::Dismiss}, Guard::Always, std::nullopt, {},
         "clears the notice; error goes to paused with a level set, inspect with a scan, else no_scan"},
    Rule{kAll, {K::Quit}, Guard::Always, std::nullopt, {}, "quitRequested()"},
    Rule{kAll, {K::SearchPacs, K::ListPacsSeries, K::RetrievePacs, K::CancelRetrieve}, Guard::Always, std::nullopt, {},
         "the kiosk's DICOM node asks the PACS; no scan is touched"},
    Rule{kAll, {K::AcknowledgeAudit}, Guard::AuditLost, std::nullopt,
         "the audit log is written: nothing to acknowledge",
         "export goes on without the audit log until it is written again; recorded in it then"},
};

inline constexpr std::array kDefaults{
    StateDefault{S::NoScan, "no scan loaded: load one first"},
    StateDefault{S::Loading, "a scan is loading"},
    StateDefault{S::Exporting, "an export is under way"},
    StateDefault{S::Error, "dismiss the error first"},
};
// clang-format on

} // namespace table

constexpr std::span<const Rule> transitionRules() {
    return table::kRules;
}
constexpr std::span<const StateDefault> stateDefaults() {
    return table::kDefaults;
}

struct Verdict {
    bool allowed = false;
    std::optional<model::State> next; // when allowed: the state that follows (nullopt: as it is)
    std::string refusal;              // when not
};
Verdict decide(model::State state, model::ActionKind kind, const Facts& facts);
constexpr model::ActionKinds allowedActions(model::State state, const Facts& facts) {
    model::ActionKinds out;
    for (const Rule& r : transitionRules()) {
        if (r.states.contains(state) && holds(r.guard, facts) && holds(r.also, facts)) {
            out.insert(r.actions);
        }
    }
    return out;
}
// The kinds some rule accepts in `state`, whatever its guard: what a screen for that state
// offers (a button that then explains its refusal, such as Run before a seed).
constexpr model::ActionKinds offeredActions(model::State state) {
    model::ActionKinds out;
    for (const Rule& r : transitionRules()) {
        if (r.states.contains(state) && r.guard != Guard::Never) {
            out.insert(r.actions);
        }
    }
    return out;
}

} // namespace steerseg::workflow
