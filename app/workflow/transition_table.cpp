#include "workflow/transition_table.hpp"

#include <array>

namespace steerseg::workflow {

namespace {

// The rule for each (state, kind), found once: the soak hands a million actions through here.
struct Index {
    std::array<std::array<const Rule*, model::kActionKindCount>, kStateCount> rule{};
    std::array<std::string_view, kStateCount> fallback{};
};

const Index& index() {
    static const Index built = [] {
        Index ix;
        for (const Rule& r : transitionRules()) {
            for (std::size_t s = 0; s < kStateCount; ++s) {
                for (std::size_t k = 0; k < model::kActionKindCount; ++k) {
                    // The first rule wins; the table test reports a second one.
                    if (r.states.contains(static_cast<model::State>(s)) &&
                        r.actions.contains(static_cast<model::ActionKind>(k)) &&
                        ix.rule[s][k] == nullptr) {
                        ix.rule[s][k] = &r;
                    }
                }
            }
        }
        for (const StateDefault& d : stateDefaults()) {
            ix.fallback[static_cast<std::size_t>(d.state)] = d.refusal;
        }
        return ix;
    }();
    return built;
}

std::string refusalIn(model::State state, std::string_view text) {
    std::string out(text);
    constexpr std::string_view kPlaceholder = "{state}";
    if (const auto at = out.find(kPlaceholder); at != std::string::npos) {
        out.replace(at, kPlaceholder.size(), model::stateName(state));
    }
    return out;
}

} // namespace

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
    case Guard::Box:
        return "a box";
    case Guard::Result:
        return "a surface in some structure";
    case Guard::AuditKept:
        return "the audit log written or its loss acknowledged";
    case Guard::AuditLost:
        return "the audit log not written, not acknowledged";
    }
    return "?";
}

Verdict decide(model::State state, model::ActionKind kind, const Facts& facts) {
    const auto s = static_cast<std::size_t>(state);
    const auto k = static_cast<std::size_t>(kind);
    if (s >= kStateCount || k >= model::kActionKindCount) {
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
    if (!holds(rule->also, facts)) {
        return {false, std::nullopt, refusalIn(state, rule->alsoRefusal)};
    }
    return {true, rule->next, {}};
}

} // namespace steerseg::workflow
