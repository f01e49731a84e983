#include "workflow/transition_table.hpp"

#include <array>

namespace steerseg::workflow {

namespace {

using K = ActionKind;
using S = State;

constexpr StateSet kAll{S::NoScan, S::Loading, S::Inspect,   S::Seeding, S::Evolving,
                        S::Paused, S::Review,  S::Exporting, S::Done,    S::Error};
constexpr StateSet kWithScan{S::Inspect, S::Seeding,   S::Evolving, S::Paused,
                             S::Review,  S::Exporting, S::Done,     S::Error};
constexpr StateSet kSteering{S::Inspect, S::Seeding, S::Evolving, S::Paused};

// Looking around: the view, the knob's selection and the tap's meaning. Also in error, where
// they leave the error's message on screen.
constexpr ActionKinds kLooking{K::RotateView,   K::ZoomView,      K::PageSlice,   K::SetSlice,
                               K::ShowSlices,   K::SetWindow,     K::SelectParam, K::CycleParam,
                               K::SetEraseMode, K::SetOutsideMode};
// Parameters and the speed: live in every steering state, evolving included.
constexpr ActionKinds kSteer{K::Probe,         K::ApplyPreset, K::SetParam,   K::NudgeParam,
                             K::NudgeSelected, K::SetSpeed,    K::MarkOutside};
constexpr ActionKinds kSteerAll{K::Probe,         K::ApplyPreset, K::SetParam,    K::NudgeParam,
                                K::NudgeSelected, K::SetSpeed,    K::MarkOutside, K::ClearExamples};
constexpr ActionKinds kExportedRefused{
    K::Probe,    K::ApplyPreset, K::SetParam,      K::NudgeParam, K::NudgeSelected,
    K::SetSpeed, K::MarkOutside, K::ClearExamples, K::AddSeed,    K::Erase};

constexpr std::string_view kNoLevelSetToRun = "no level set to evolve: add a seed first";
constexpr std::string_view kNothingToExport = "nothing to export: add a seed first";
constexpr std::string_view kExportNote =
    "then done; a failure goes back to review with the writer's message, the work kept";

// clang-format off
constexpr std::array kRules{
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
    Rule{{S::Review}, {K::AddSeed, K::Erase}, Guard::Never, std::nullopt,
         "go back to steering to edit the surface"},
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
    Rule{{S::Seeding, S::Evolving, S::Paused}, {K::Finish}, Guard::LevelSet, S::Review,
         "nothing to review: add a seed first"},
    Rule{{S::Evolving, S::Paused}, {K::Proceed}, Guard::LevelSet, S::Review,
         "nothing to review: add a seed first"},
    Rule{{S::Review}, {K::Finish}, Guard::Always, std::nullopt, {}},
    Rule{{S::Inspect, S::Done}, {K::Finish}, Guard::Never, std::nullopt,
         "nothing to finish in {state}"},
    Rule{{S::Review}, {K::Resume, K::Back}, Guard::Always, S::Paused, {}},
    Rule{{S::NoScan, S::Loading, S::Inspect, S::Seeding, S::Evolving, S::Paused, S::Done},
         {K::Resume}, Guard::Never, std::nullopt, "resume goes from review back to steering"},
    // Export.
    Rule{{S::Review, S::Paused}, {K::Export}, Guard::LevelSet, S::Exporting, kNothingToExport,
         kExportNote},
    Rule{{S::Review}, {K::Proceed}, Guard::LevelSet, S::Exporting, kNothingToExport, kExportNote},
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
    Rule{kAll, {K::Dismiss}, Guard::Always, std::nullopt, {},
         "clears the notice; error goes to paused with a level set, inspect with a scan, else no_scan"},
    Rule{kAll, {K::Quit}, Guard::Always, std::nullopt, {}, "quitRequested()"},
};

constexpr std::array kDefaults{
    StateDefault{S::NoScan, "no scan loaded: load one first"},
    StateDefault{S::Loading, "a scan is loading"},
    StateDefault{S::Exporting, "an export is under way"},
    StateDefault{S::Error, "dismiss the error first"},
};
// clang-format on

// The rule for each (state, kind), found once: the soak hands a million actions through here.
struct Index {
    std::array<std::array<const Rule*, kActionKindCount>, kStateCount> rule{};
    std::array<std::string_view, kStateCount> fallback{};
};

const Index& index() {
    static const Index built = [] {
        Index ix;
        for (const Rule& r : kRules) {
            for (std::size_t s = 0; s < kStateCount; ++s) {
                for (std::size_t k = 0; k < kActionKindCount; ++k) {
                    // The first rule wins; the table test reports a second one.
                    if (r.states.contains(static_cast<State>(s)) &&
                        r.actions.contains(static_cast<ActionKind>(k)) &&
                        ix.rule[s][k] == nullptr) {
                        ix.rule[s][k] = &r;
                    }
                }
            }
        }
        for (const StateDefault& d : kDefaults) {
            ix.fallback[static_cast<std::size_t>(d.state)] = d.refusal;
        }
        return ix;
    }();
    return built;
}

std::string refusalIn(State state, std::string_view text) {
    std::string out(text);
    constexpr std::string_view kPlaceholder = "{state}";
    if (const auto at = out.find(kPlaceholder); at != std::string::npos) {
        out.replace(at, kPlaceholder.size(), stateName(state));
    }
    return out;
}

} // namespace

Facts factsOf(const Status& status) {
    return {status.hasLevelSet, status.unexported, status.canUndo, status.canRedo,
            !status.insideExamples.empty() || !status.outsideExamples.empty()};
}

std::string_view guardName(Guard guard) {
    switch (guard) {
    case Guard::Always:
        return "always";
    case Guard::Never:
        return "never";
    case Guard::LevelSet:
        return "a level set";
    case Guard::NoUnexportedWork:
        return "no unexported work";
    case Guard::CanUndo:
        return "something to undo";
    case Guard::CanRedo:
        return "something to redo";
    case Guard::Examples:
        return "examples";
    }
    return "?";
}

bool holds(Guard guard, const Facts& facts) {
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
    }
    return false;
}

std::span<const Rule> transitionRules() {
    return kRules;
}

std::span<const StateDefault> stateDefaults() {
    return kDefaults;
}

Verdict decide(State state, ActionKind kind, const Facts& facts) {
    const auto s = static_cast<std::size_t>(state);
    const auto k = static_cast<std::size_t>(kind);
    if (s >= kStateCount || k >= kActionKindCount) {
        return {false, std::nullopt, "unknown state or action"};
    }
    const Index& ix = index();
    const Rule* rule = ix.rule[s][k];
    if (rule == nullptr) {
        return {false, std::nullopt, refusalIn(state, ix.fallback[s])};
    }
    if (!holds(rule->guard, facts)) {
        return {false, std::nullopt, refusalIn(state, rule->refusal)};
    }
    return {true, rule->next, {}};
}

ActionKinds allowedActions(State state, const Facts& facts) {
    ActionKinds out;
    const auto s = static_cast<std::size_t>(state);
    if (s >= kStateCount) {
        return out;
    }
    for (std::size_t k = 0; k < kActionKindCount; ++k) {
        const Rule* rule = index().rule[s][k];
        if (rule != nullptr && holds(rule->guard, facts)) {
            out.insert(static_cast<ActionKind>(k));
        }
    }
    return out;
}

ActionKinds offeredActions(State state) {
    ActionKinds out;
    const auto s = static_cast<std::size_t>(state);
    if (s >= kStateCount) {
        return out;
    }
    for (std::size_t k = 0; k < kActionKindCount; ++k) {
        const Rule* rule = index().rule[s][k];
        if (rule != nullptr && rule->guard != Guard::Never) {
            out.insert(static_cast<ActionKind>(k));
        }
    }
    return out;
}

} // namespace steerseg::workflow
