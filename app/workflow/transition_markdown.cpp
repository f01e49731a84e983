#include "workflow/transition_markdown.hpp"

#include "workflow/transition_table.hpp"

namespace steerseg::workflow {

namespace {

std::string statesText(const StateSet& states) {
    std::string out;
    std::size_t n = 0;
    for (std::size_t s = 0; s < kStateCount; ++s) {
        if (states.contains(static_cast<model::State>(s))) {
            out += (out.empty() ? "" : ", ") +
                   std::string(model::stateName(static_cast<model::State>(s)));
            ++n;
        }
    }
    return n == kStateCount ? std::string("any") : out;
}

std::string actionsText(const model::ActionKinds& actions) {
    std::string out;
    for (std::size_t k = 0; k < model::kActionKindCount; ++k) {
        if (actions.contains(static_cast<model::ActionKind>(k))) {
            out += (out.empty() ? "" : ", ") +
                   std::string(model::actionKindName(static_cast<model::ActionKind>(k)));
        }
    }
    return out;
}

std::string row(const std::string& states, const std::string& actions, std::string_view needs,
                std::string_view next, std::string_view refusal, std::string_view note) {
    std::string out = "| " + states + " | " + actions + " |";
    for (const std::string_view cell : {needs, next, refusal, note}) {
        out += cell.empty() ? std::string(" |") : " " + std::string(cell) + " |";
    }
    return out + "\n";
}

} // namespace

std::string transitionTableMarkdown() {
    std::string out = "| state | action | needs | next | refused with | note |\n"
                      "|---|---|---|---|---|---|\n";
    for (const Rule& r : transitionRules()) {
        const bool never = r.guard == Guard::Never;
        std::string needs(r.guard == Guard::Always ? "" : guardName(r.guard));
        std::string refusal(r.refusal);
        if (r.also != Guard::Always) {
            needs += "; " + std::string(guardName(r.also));
            refusal += "; " + std::string(r.alsoRefusal);
        }
        const std::string next = never    ? ""
                                 : r.next ? std::string(model::stateName(*r.next))
                                          : "same";
        out += row(statesText(r.states), actionsText(r.actions), needs, next, refusal, r.note);
    }
    for (const StateDefault& d : stateDefaults()) {
        out += row(std::string(model::stateName(d.state)), "any other", guardName(Guard::Never), "",
                   d.refusal, "");
    }
    return out;
}

} // namespace steerseg::workflow
