#pragma once

// The workflow's rules as data: in which states an action kind is accepted, under which guard,
// which state follows, and the one-line refusal otherwise. Workflow::handle runs it before an
// action's own code, Status::allowed publishes it, and docs/workflow.md prints it
// (transition_markdown.hpp; a unit test keeps the two equal).
#include "workflow/action.hpp"
#include "workflow/status.hpp"

#include <cstddef>
#include <cstdint>
#include <initializer_list>
#include <optional>
#include <span>
#include <string>
#include <string_view>

namespace steerseg::workflow {

inline constexpr std::size_t kStateCount = static_cast<std::size_t>(State::Error) + 1;

class StateSet {
  public:
    constexpr StateSet() = default;
    constexpr StateSet(std::initializer_list<State> states) {
        for (const State s : states) {
            bits_ |= bit(s);
        }
    }
    [[nodiscard]] constexpr bool contains(State state) const { return (bits_ & bit(state)) != 0; }

  private:
    static constexpr std::uint16_t bit(State state) {
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
    bool examples = false; // classify has an inside or an outside example
};
// The same facts as a status shows them (a status built by hand, a test's).
Facts factsOf(const Status& status);

enum class Guard { Always, Never, LevelSet, NoUnexportedWork, CanUndo, CanRedo, Examples };
std::string_view guardName(Guard guard); // the docs' words: "always", "level set", ...
bool holds(Guard guard, const Facts& facts);

struct Rule {
    StateSet states;
    ActionKinds actions;
    Guard guard = Guard::Always;
    // nullopt: the state stays, unless the action's own code moves it (`note` says where).
    std::optional<State> next;
    std::string_view refusal; // when the guard fails; "{state}" stands for the state's name
    std::string_view note = {};
};

// The refusal of every action kind no rule names in a state.
struct StateDefault {
    State state;
    std::string_view refusal;
};

// The rules, in the docs' order; at most one names any (state, action kind), and a state
// without a default has a rule for every kind (workflow_table_test).
std::span<const Rule> transitionRules();
std::span<const StateDefault> stateDefaults();

struct Verdict {
    bool allowed = false;
    std::optional<State> next; // when allowed: the state that follows (nullopt: as it is)
    std::string refusal;       // when not
};
Verdict decide(State state, ActionKind kind, const Facts& facts);
ActionKinds allowedActions(State state, const Facts& facts);
// The kinds some rule accepts in `state`, whatever its guard: what a screen for that state
// offers (a button that then explains its refusal, such as Run before a seed).
ActionKinds offeredActions(State state);

} // namespace steerseg::workflow
