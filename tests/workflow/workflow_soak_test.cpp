// A million random actions, frames and injected failures through the workflow over the fake
// engine (fixed seed; STEERSEG_SOAK_ACTIONS sets the count), checking the state machine's
// invariants after each: no exception, a valid state, only actions the status allowed accepted,
// parameters finite and in range, a level set whenever evolving, bounded undo and snapshots (none
// leaked), the status agreeing with the engine, and no call the engine should never see.
#include "model/structure.hpp"
#include "support/fake_engine.hpp"
#include "workflow/transition_table.hpp"
#include "workflow/workflow.hpp"

#include <array>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <gtest/gtest.h>
#include <iostream>
#include <limits>
#include <nlohmann/json.hpp>
#include <random>
#include <string>

namespace steerseg::test {
namespace {

using namespace workflow;

using namespace model;

long long soakCount() {
    if (const char* env = std::getenv("STEERSEG_SOAK_ACTIONS")) {
        char* end = nullptr;
        const long long n = std::strtoll(env, &end, 10);
        if (end != env && *end == '\0' && n > 0) {
            return n;
        }
    }
    return 1000000;
}

class Generator {
  public:
    explicit Generator(std::uint32_t seed) : rng_(seed) {}

    double uniform(double lo, double hi) { return std::uniform_real_distribution<>(lo, hi)(rng_); }
    int integer(int lo, int hi) { return std::uniform_int_distribution<>(lo, hi)(rng_); }
    bool chance(double p) { return uniform(0.0, 1.0) < p; }

    // Mostly sensible numbers, sometimes hostile ones.
    double number(double lo, double hi) {
        if (chance(0.01)) {
            constexpr std::array<double, 5> bad{
                std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::infinity(),
                -std::numeric_limits<double>::infinity(), 1e308, -1e308};
            return bad[static_cast<std::size_t>(integer(0, 4))];
        }
        return uniform(lo, hi);
    }
    glm::dvec3 voxel() { return {number(-2.0, 18.0), number(-2.0, 14.0), number(-2.0, 10.0)}; }
    Param param() { return static_cast<Param>(chance(0.01) ? 7 : integer(0, 3)); }
    SliceAxis axis() { return static_cast<SliceAxis>(chance(0.01) ? 5 : integer(0, 2)); }

    Action action() {
        // Weighted towards what an operator does most: steering, seeding, looking.
        switch (integer(0, 56)) {
        case 0:
            return LoadScan{chance(0.05) ? "" : "scan.nii.gz"};
        case 1:
        case 2:
            return Probe{voxel(), number(-1.0, 8.0)};
        case 3:
            return ApplyPreset{chance(0.8) ? "soft" : "nonexistent"};
        case 4:
        case 5:
            return SetParam{param(), number(-1500.0, 1500.0)};
        case 6:
        case 7:
            return NudgeParam{param(), number(-5.0, 5.0)};
        case 8:
            return NudgeSelected{number(-5.0, 5.0)};
        case 9:
            return SelectParam{param()};
        case 10:
            return CycleParam{integer(-5, 5)};
        case 11:
            return SetWindow{number(-500.0, 500.0), number(-10.0, 2000.0)};
        case 12:
        case 13:
        case 14:
            return AddSeed{voxel(), number(-1.0, 5.0)};
        case 15:
        case 16:
            return Erase{voxel(), number(-1.0, 5.0)};
        case 17:
            return SetEraseMode{chance(0.5)};
        case 18:
        case 19:
            return Run{};
        case 20:
            return Pause{};
        case 21:
            return ToggleRun{};
        case 22:
            return Finish{};
        case 23:
            return Resume{};
        case 24:
            return Export{chance(0.5) ? "" : "soak-mask.nii.gz"};
        case 25:
        case 26:
            return Undo{};
        case 27:
            return Redo{};
        case 28:
            return Restart{};
        case 29:
        case 30:
        case 31:
            return Proceed{};
        case 32:
            return Back{};
        case 33:
            return Dismiss{};
        case 34:
            return RotateView{number(-90.0, 90.0), number(-90.0, 90.0)};
        case 35:
            return ZoomView{number(-0.5, 3.0)};
        case 36:
            return PageSlice{axis(), integer(-20, 20)};
        case 37:
            return SetSlice{axis(), integer(-5, 30)};
        case 38:
            return ShowSlices{axis(), axis()};
        case 39:
            return Quit{};
        case 40:
            return SetSpeed{static_cast<model::SpeedKind>(chance(0.01) ? 9 : integer(0, 2))};
        case 41:
        case 42:
            return MarkOutside{voxel(), number(-1.0, 8.0)};
        case 43:
            return ClearExamples{};
        case 44:
            return SetOutsideMode{chance(0.5)};
        case 45:
        case 46: {
            model::PaintStroke stroke{
                static_cast<model::StrokeMode>(chance(0.01) ? 7 : integer(0, 2)),
                {},
                number(-1.0, 5.0)};
            for (int p = integer(chance(0.01) ? 0 : 1, 4); p > 0; --p) {
                stroke.points.push_back(voxel());
            }
            return stroke;
        }
        case 47:
            return Correct{voxel(), chance(0.7), number(-1.0, 5.0)};
        case 48: {
            // Corners mostly in the fake's 16 x 12 x 8, sometimes inverted or beyond it.
            const glm::ivec3 a(integer(-1, 16), integer(-1, 12), integer(-1, 8));
            const glm::ivec3 b(integer(-1, 16), integer(-1, 12), integer(-1, 8));
            return SetBox{chance(0.9) ? model::Box{glm::min(a, b), glm::max(a, b)}
                                      : model::Box{a, b}};
        }
        case 49:
            return ClearBox{};
        case 50:
            return SetBoxMode{chance(0.5), chance(0.5)
                                               ? std::optional<model::BoxFace>(
                                                     model::BoxFace{integer(0, 2), chance(0.5)})
                                               : std::nullopt};
        case 51:
        case 52: {
            // A few names, so that adds collide, selects find one and renames clash; now and
            // then an op or a colour out of range.
            static const std::array<std::string, 4> names{std::string(model::kFirstStructureName),
                                                          "Liver", "Spleen", ""};
            model::EditStructure edit;
            edit.op = static_cast<model::StructureOp>(chance(0.01) ? 9 : integer(0, 6));
            edit.name = names[static_cast<std::size_t>(integer(0, 3))];
            edit.to = names[static_cast<std::size_t>(integer(0, 3))];
            edit.colour = {number(-0.1, 1.0), number(0.0, 1.0), number(0.0, 1.0)};
            return edit;
        }
        case 53: {
            // The PACS's: now and then a key or a UID the workflow must refuse.
            model::SearchPacs search;
            search.keys.patientId = chance(0.05) ? std::string(70, 'X') : "PID-A";
            search.keys.studyDate = chance(0.5) ? "last_7_days" : "";
            return search;
        }
        case 54:
            return model::RetrievePacs{"", chance(0.05) ? "1.2.x" : "1.2.840.5", ""};
        case 55:
            return model::CancelRetrieve{};
        case 56:
            return model::ListPacsSeries{"", chance(0.05) ? "1.2.x" : "1.2.840.5"};
        default:
            return Run{};
        }
    }

  private:
    std::mt19937 rng_;
};

bool within(double v, const ParamRange& r) {
    return std::isfinite(v) && v >= r.min && v <= r.max;
}

// The first broken invariant, or "" when all hold.
std::string broken(const Workflow& wf, const FakeEngine& engine, std::size_t maxUndo) {
    const Status& s = wf.status();
    if (static_cast<int>(s.state) < 0 || s.state > State::Error || s.state == State::Exporting) {
        return "state " + std::to_string(static_cast<int>(s.state)) + " after an action";
    }
    if (engine.misuse() != 0) {
        return "engine misused: " + engine.lastMisuse();
    }
    const bool scan = s.scan.dims.x > 0;
    if (scan != (s.state != State::NoScan && s.state != State::Loading)) {
        return "scan present in " + std::string(stateName(s.state));
    }
    if (scan) {
        const float p[3] = {s.params.T, s.params.eps, s.params.alpha};
        for (std::size_t i = 0; i < 3; ++i) {
            if (!within(static_cast<double>(p[i]), s.ranges[i])) {
                return std::string(paramName(static_cast<Param>(i))) + " out of range";
            }
        }
        if (!within(s.radius, s.ranges[3])) {
            return "brush radius out of range";
        }
        const model::LevelSetParams& e = engine.params();
        if (e.T != s.params.T || e.eps != s.params.eps || e.alpha != s.params.alpha) {
            return "parameters differ from the engine's";
        }
        if (engine.speedKind() != s.speedInForce ||
            (s.speed != model::SpeedKind::Classify && s.speedInForce != s.speed)) {
            return "the speed differs from the engine's or the choice";
        }
        if (s.box) {
            try {
                model::validateBox(*s.box, s.scan.dims);
            } catch (const std::invalid_argument& why) {
                return std::string("a box that does not fit the scan: ") + why.what();
            }
        }
        if (!engine.speeds.empty() && engine.speeds.back().box != s.box) {
            return "the box differs from the engine's";
        }
        if (s.insideExamples.size() > kMaxExamples || s.outsideExamples.size() > kMaxExamples) {
            return "more examples than kept";
        }
        if (s.outsideMode && s.eraseMode) {
            return "outside and erase mode both on";
        }
        for (int a = 0; a < 3; ++a) {
            if (s.view.slice[a] < -1 || s.view.slice[a] >= s.scan.sliceCount[a]) {
                return "slice outside the scan";
            }
        }
    }
    if (s.state == State::Evolving && !engine.hasLevelSet()) {
        return "evolving without a level set";
    }
    if (s.hasLevelSet != engine.hasLevelSet() || s.iterations != engine.stats().iterations ||
        s.volumeMl != engine.volumeMl()) {
        return "status differs from the engine";
    }
    if (wf.undoDepth() > maxUndo || wf.undoDepth() + wf.redoDepth() > maxUndo) {
        return "undo deeper than its limit";
    }
    if (s.canUndo != (wf.undoDepth() > 0) || s.canRedo != (wf.redoDepth() > 0)) {
        return "canUndo/canRedo wrong";
    }
    if (engine.liveSnapshots() > 2 * maxUndo + 2 || engine.liveSnapshots() != wf.heldSnapshots()) {
        return "snapshots: " + std::to_string(engine.liveSnapshots()) + " live, " +
               std::to_string(wf.heldSnapshots()) + " held";
    }
    if (s.seeds < 0 || s.erasures < 0 || !std::isfinite(s.view.zoom) || s.view.zoom <= 0.0) {
        return "counts or zoom invalid";
    }
    if (s.allowed != allowedActions(s.state, factsOf(s))) {
        return "the allowed actions differ from the table's for the status";
    }
    if (s.message.find('\n') != std::string::npos) {
        return "a message of several lines";
    }
    return {};
}

struct Walk {
    std::array<long long, 10> visits{};
    std::array<long long, std::variant_size_v<Action>> accepted{};
};

Settings soakSettings() {
    Settings settings;
    settings.presets = {{"soft", 40.0, 80.0, 0.7, 40.0, 400.0, "ct_soft"}};
    settings.epsFloor = 10.0;
    settings.maxUndo = 12;
    settings.exportFolder = std::filesystem::path(testing::TempDir()) / "workflow-soak";
    settings.clock = [] { return std::chrono::system_clock::time_point{}; };
    return settings;
}

// `count` random steps; stops at (and reports) the first thrown exception or broken invariant.
void walk(long long count, AuditLog* audit, Walk& out) {
    FakeEngine engine;
    engine.loadPolls = 1;
    engine.convergeAfter = 60;
    const Settings settings = soakSettings();
    const auto maxUndo = static_cast<std::size_t>(settings.maxUndo);
    Workflow wf(engine, settings, audit);
    Generator gen(20261123U);
    for (long long n = 0; n < count; ++n) {
        std::string what;
        const int kind = gen.integer(0, 99);
        try {
            if (kind < 70) {
                const Action a = gen.action();
                what = actionName(a);
                const bool allowed = wf.status().allowed.contains(kindOf(a));
                if (wf.handle(a).accepted) {
                    ++out.accepted[a.index()];
                    if (!allowed) {
                        FAIL() << "step " << n << ": " << what << " accepted, not allowed";
                    }
                }
            } else if (kind < 85) {
                what = "evolve";
                wf.evolve(gen.integer(-1, 16));
            } else if (kind < 97) {
                what = "update";
                wf.update();
            } else {
                // Failures on demand, each for a while.
                what = "failures";
                engine.loadError = gen.chance(0.2) ? "scan.nii.gz: truncated" : "";
                engine.exportError = gen.chance(0.2) ? "disk full" : "";
                engine.stepError = gen.chance(0.05) ? "GPU lost" : "";
                engine.editError = gen.chance(0.05) ? "edit failed" : "";
                engine.snapshotError = gen.chance(0.05) ? "out of memory" : "";
                engine.speedError = gen.chance(0.05) ? "speed refused" : "";
            }
        } catch (const std::exception& e) {
            FAIL() << "step " << n << " (" << what << ") threw: " << e.what();
        }
        ++out.visits[static_cast<std::size_t>(wf.state())];
        const std::string b = broken(wf, engine, maxUndo);
        if (!b.empty()) {
            FAIL() << "step " << n << " (" << what << ", now " << stateName(wf.state())
                   << "): " << b;
        }
    }
}

TEST(WorkflowSoak, RandomActionsKeepEveryInvariant) {
    const long long count = soakCount();
    Walk w;
    const auto start = std::chrono::steady_clock::now();
    walk(count, nullptr, w);
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    std::cout << count << " steps in " << seconds << " s; steps per state:";
    for (std::size_t i = 0; i < w.visits.size(); ++i) {
        std::cout << ' ' << stateName(static_cast<State>(i)) << '=' << w.visits[i];
    }
    std::cout << "\naccepted per action:";
    for (std::size_t i = 0; i < w.accepted.size(); ++i) {
        std::cout << ' ' << w.accepted[i];
    }
    std::cout << '\n';
    // The walk went everywhere worth checking (a broken generator would idle in one state).
    if (count >= 100000) {
        for (const State s :
             {State::NoScan, State::Loading, State::Inspect, State::Seeding, State::Evolving,
              State::Paused, State::Review, State::Done, State::Error}) {
            EXPECT_GT(w.visits[static_cast<std::size_t>(s)], 100) << stateName(s);
        }
        for (std::size_t i = 0; i < w.accepted.size(); ++i) {
            // acknowledge_audit has a use only while the audit log is lost (workflow_audit_test).
            if (static_cast<model::ActionKind>(i) != model::ActionKind::AcknowledgeAudit) {
                EXPECT_GT(w.accepted[i], 0) << "action " << i << " never accepted";
            }
        }
    }
}

// The same walk, shorter, with the audit log on: every line it wrote parses and names its event.
TEST(WorkflowSoak, AuditLogOfARandomWalkParses) {
    const std::filesystem::path path =
        std::filesystem::path(testing::TempDir()) / "workflow-soak-audit.jsonl";
    std::filesystem::remove(path);
    {
        AuditLog log(path);
        Walk w;
        walk(20000, &log, w);
        ASSERT_TRUE(log.ok());
    }
    std::ifstream in(path);
    std::string line;
    long long lines = 0;
    while (std::getline(in, line)) {
        const nlohmann::json j = nlohmann::json::parse(line);
        ASSERT_TRUE(j.contains("event") && j.contains("state") && j.contains("time")) << line;
        ++lines;
    }
    EXPECT_GT(lines, 10000);
}

} // namespace
} // namespace steerseg::test
