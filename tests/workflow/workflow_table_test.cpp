// The transition table: well formed (one rule per state and action kind), the rules the
// workflow actually follows (every kind in every state the operator reaches, against
// Status::allowed and the refusal text), and the table docs/workflow.md shows.
#include "support/workflow_rig.hpp"
#include "workflow/transition_markdown.hpp"
#include "workflow/transition_table.hpp"

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <gtest/gtest.h>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

namespace steerseg::test {
namespace {

using namespace workflow;

using namespace model;

std::string pair(State s, ActionKind k) {
    return std::string(stateName(s)) + " + " + std::string(actionKindName(k));
}

TEST(WorkflowTable, OneRuleOrAStateDefaultForEveryStateAndAction) {
    std::vector<std::optional<std::string_view>> defaults(kStateCount);
    for (const StateDefault& d : stateDefaults()) {
        const auto s = static_cast<std::size_t>(d.state);
        EXPECT_FALSE(defaults[s]) << stateName(d.state) << " has two defaults";
        EXPECT_FALSE(d.refusal.empty()) << stateName(d.state);
        defaults[s] = d.refusal;
    }
    for (std::size_t s = 0; s < kStateCount; ++s) {
        for (std::size_t k = 0; k < kActionKindCount; ++k) {
            const auto state = static_cast<State>(s);
            const auto kind = static_cast<ActionKind>(k);
            int rules = 0;
            for (const Rule& r : transitionRules()) {
                rules += r.states.contains(state) && r.actions.contains(kind) ? 1 : 0;
            }
            EXPECT_LE(rules, 1) << pair(state, kind) << " has " << rules << " rules";
            EXPECT_TRUE(rules == 1 || defaults[s]) << pair(state, kind) << " has no rule";
        }
    }
}

TEST(WorkflowTable, RulesSayWhyExactlyWhenTheyCanRefuse) {
    for (const Rule& r : transitionRules()) {
        std::string what;
        for (std::size_t k = 0; k < kActionKindCount; ++k) {
            if (r.actions.contains(static_cast<ActionKind>(k))) {
                what += std::string(actionKindName(static_cast<ActionKind>(k))) + " ";
            }
        }
        EXPECT_FALSE(what.empty()) << "a rule without actions";
        EXPECT_EQ(r.refusal.empty(), r.guard == Guard::Always) << what;
        if (r.guard == Guard::Never) {
            EXPECT_FALSE(r.next) << what << "refuses and moves";
        }
    }
    // Everything is accepted somewhere (else a kind would be dead vocabulary).
    Facts all;
    all.levelSet = all.canUndo = all.canRedo = all.examples = all.box = all.result = true;
    Facts auditLost = all; // acknowledge_audit has a use only then
    auditLost.auditLost = true;
    for (std::size_t k = 0; k < kActionKindCount; ++k) {
        bool somewhere = false;
        for (std::size_t s = 0; s < kStateCount; ++s) {
            for (const Facts& facts : {all, auditLost}) {
                somewhere =
                    somewhere ||
                    decide(static_cast<State>(s), static_cast<ActionKind>(k), facts).allowed;
            }
        }
        EXPECT_TRUE(somewhere) << actionKindName(static_cast<ActionKind>(k));
    }
}

TEST(WorkflowTable, GuardsDecideAndRefusalsNameTheState) {
    const Facts none;
    Facts seeded;
    seeded.levelSet = true;
    EXPECT_FALSE(decide(State::Paused, ActionKind::Run, none).allowed);
    EXPECT_EQ(decide(State::Paused, ActionKind::Run, none).refusal,
              "no level set to evolve: add a seed first");
    const Verdict run = decide(State::Paused, ActionKind::Run, seeded);
    EXPECT_TRUE(run.allowed);
    EXPECT_EQ(run.next, State::Evolving);
    EXPECT_EQ(decide(State::Evolving, ActionKind::Back, seeded).refusal,
              "no step back from evolving");
    EXPECT_EQ(decide(State::Error, ActionKind::Run, seeded).refusal, "dismiss the error first");
    EXPECT_TRUE(allowedActions(State::Paused, seeded).contains(ActionKind::Run));
    EXPECT_FALSE(allowedActions(State::Paused, none).contains(ActionKind::Run));
    EXPECT_TRUE(offeredActions(State::Paused).contains(ActionKind::Run)) << "guard aside";
    EXPECT_FALSE(offeredActions(State::Review).contains(ActionKind::Run));
}

const glm::dvec3 kIn{8.0, 6.0, 4.0};

// An action of each kind with arguments the workflow accepts, so that only the table (and
// not the arguments) can refuse it.
Action sample(ActionKind kind) {
    switch (kind) {
    case ActionKind::LoadScan:
        return LoadScan{"b.nii"};
    case ActionKind::Probe:
        return Probe{kIn, 5.0};
    case ActionKind::ApplyPreset:
        return ApplyPreset{"CT bone"};
    case ActionKind::SetParam:
        return SetParam{Param::Alpha, 0.5};
    case ActionKind::NudgeParam:
        return NudgeParam{Param::T, 1.0};
    case ActionKind::NudgeSelected:
        return NudgeSelected{-1.0};
    case ActionKind::SelectParam:
        return SelectParam{Param::Eps};
    case ActionKind::CycleParam:
        return CycleParam{1};
    case ActionKind::SetWindow:
        return SetWindow{40.0, 400.0};
    case ActionKind::AddSeed:
        return AddSeed{{4.0, 4.0, 3.0}, 1.0};
    case ActionKind::Erase:
        return Erase{kIn, 1.0};
    case ActionKind::SetEraseMode:
        return SetEraseMode{true};
    case ActionKind::SetSpeed:
        return SetSpeed{model::SpeedKind::Edge};
    case ActionKind::MarkOutside:
        return MarkOutside{{2.0, 2.0, 2.0}, 2.0};
    case ActionKind::SetOutsideMode:
        return SetOutsideMode{true};
    case ActionKind::PaintStroke: // outside: a stroke no state refuses for its mode's sake
        return model::PaintStroke{
            model::StrokeMode::Outside, {{2.0, 2.0, 2.0}, {5.0, 2.0, 2.0}}, 1.0};
    case ActionKind::ShowSlices:
        return ShowSlices{SliceAxis::Sagittal, SliceAxis::Axial};
    case ActionKind::RotateView:
        return RotateView{10.0, 5.0};
    case ActionKind::ZoomView:
        return ZoomView{1.5};
    case ActionKind::PageSlice:
        return PageSlice{SliceAxis::Axial, 1};
    case ActionKind::SetSlice:
        return SetSlice{SliceAxis::Coronal, 3};
    case ActionKind::EditStructure: // a rename: the kinds that move the state have their tests
        return model::EditStructure{
            model::StructureOp::Rename, std::string(model::kFirstStructureName), "Liver", {}};
    case ActionKind::RetrievePacs:
        return model::RetrievePacs{"", "1.2.840.5", ""};
    case ActionKind::ListPacsSeries:
        return model::ListPacsSeries{"", "1.2.840.5"};
    default:
        break; // the kinds without arguments: their default value
    }
    Action out;
    const auto k = static_cast<std::size_t>(kind);
    // The variant's alternative number k, default-constructed.
    [&]<std::size_t... I>(std::index_sequence<I...>) {
        ((I == k ? (out = std::variant_alternative_t<I, Action>{}, true) : false) || ...);
    }
    (std::make_index_sequence<kActionKindCount>{});
    return out;
}

// Every action kind in every state the operator reaches: accepted exactly when the status
// said it was allowed, refused with the table's words, and in the table's next state.
TEST(WorkflowTable, TheWorkflowFollowsItsTable) {
    for (const State from :
         {State::NoScan, State::Loading, State::Inspect, State::Seeding, State::Evolving,
          State::Paused, State::Review, State::Done, State::Error}) {
        for (std::size_t k = 0; k < kActionKindCount; ++k) {
            const auto kind = static_cast<ActionKind>(k);
            Rig rig;
            rig.driveTo(from);
            ASSERT_EQ(rig.state(), from);
            const Status before = rig.status();
            EXPECT_EQ(before.allowed, allowedActions(from, factsOf(before))) << pair(from, kind);
            const Verdict verdict = decide(from, kind, factsOf(before));
            const Action action = sample(kind);
            ASSERT_EQ(kindOf(action), kind);
            const Workflow::Outcome out = rig.act(action);
            EXPECT_EQ(out.accepted, before.allowed.contains(kind))
                << pair(from, kind) << ": " << out.reason;
            if (!verdict.allowed) {
                EXPECT_EQ(out.reason, verdict.refusal) << pair(from, kind);
                EXPECT_EQ(rig.state(), from) << pair(from, kind);
            } else if (verdict.next == State::Exporting) {
                EXPECT_EQ(rig.state(), State::Done) << pair(from, kind) << ": through exporting";
            } else if (!(kind == ActionKind::Dismiss && from == State::Error)) {
                EXPECT_EQ(rig.state(), verdict.next.value_or(from)) << pair(from, kind);
            }
            EXPECT_EQ(rig.status().allowed, allowedActions(rig.state(), factsOf(rig.status())))
                << pair(from, kind) << ": the status publishes the table's answer";
        }
    }
}

// docs/workflow.md beside the sources: the test may run from a build folder anywhere below.
std::optional<std::filesystem::path> workflowDoc() {
    std::vector<std::filesystem::path> roots;
    if (const char* src = std::getenv("STEERSEG_SOURCE_DIR"); src != nullptr && *src != '\0') {
        roots.emplace_back(src);
    }
    if (const std::filesystem::path file(__FILE__); file.is_absolute()) {
        roots.push_back(file.parent_path().parent_path().parent_path());
    }
    std::error_code ec;
    for (std::filesystem::path dir = std::filesystem::current_path(ec); !dir.empty();
         dir = dir.parent_path()) {
        roots.push_back(dir);
        if (dir == dir.root_path()) {
            break;
        }
    }
    for (const std::filesystem::path& root : roots) {
        if (std::filesystem::exists(root / "docs" / "workflow.md", ec) &&
            std::filesystem::exists(root / "app" / "workflow" / "transition_table.hpp", ec)) {
            return root / "docs" / "workflow.md";
        }
    }
    return std::nullopt;
}

std::vector<std::string> lines(std::istream& in) {
    std::vector<std::string> out;
    for (std::string line; std::getline(in, line);) {
        out.push_back(line);
    }
    return out;
}

TEST(WorkflowTable, TheDocsShowTheTable) {
    const std::optional<std::filesystem::path> doc = workflowDoc();
    ASSERT_TRUE(doc) << "docs/workflow.md not found (set STEERSEG_SOURCE_DIR)";
    std::ifstream file(*doc);
    const std::vector<std::string> all = lines(file);
    const std::string begin = "<!-- transition table: generated by transitionTableMarkdown()";
    const std::string end = "<!-- end of transition table -->";
    std::vector<std::string> docs;
    bool inside = false;
    bool found = false;
    for (const std::string& line : all) {
        if (line.rfind(begin, 0) == 0) {
            inside = found = true;
        } else if (line == end) {
            inside = false;
        } else if (inside) {
            docs.push_back(line);
        }
    }
    ASSERT_TRUE(found) << doc->string() << " lacks the line starting " << begin;
    std::istringstream generated(transitionTableMarkdown());
    const std::vector<std::string> code = lines(generated);
    for (std::size_t i = 0; i < std::max(docs.size(), code.size()); ++i) {
        const std::string d = i < docs.size() ? docs[i] : "(missing)";
        const std::string c = i < code.size() ? code[i] : "(missing)";
        if (d != c) {
            ADD_FAILURE() << doc->string() << ": the transition table's line " << i + 1
                          << " differs from the code's\n  docs: " << d << "\n  code: " << c
                          << "\nThe code's table, to paste between the markers:\n"
                          << transitionTableMarkdown();
            break;
        }
    }
}

} // namespace
} // namespace steerseg::test
