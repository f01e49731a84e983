// The speed choice (issue 13): threshold, edge and classify, the classifier's examples (the
// probes inside, the outside marks), the states that allow them, undo, the engine's refusals
// and the audit records.
#include "model/speed_kind.hpp"
#include "support/workflow_rig.hpp"

#include <filesystem>
#include <fstream>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

namespace steerseg::test {
namespace {

using namespace workflow;

using namespace model;
using model::SpeedKind;
namespace fs = std::filesystem;

const glm::dvec3 kInside{8.0, 6.0, 4.0};
const glm::dvec3 kOutside{1.0, 1.0, 1.0};

TEST(WorkflowSpeed, NamesAndBindings) {
    for (SpeedKind k : model::kSpeedKinds) {
        EXPECT_EQ(model::parseSpeedKind(model::speedKindName(k)), k);
    }
    EXPECT_FALSE(model::parseSpeedKind("gradient"));
    EXPECT_EQ(actionName(SetSpeed{}), "set_speed");
    EXPECT_EQ(actionName(MarkOutside{}), "mark_outside");
    EXPECT_EQ(actionName(ClearExamples{}), "clear_examples");
    EXPECT_EQ(actionName(SetOutsideMode{}), "set_outside_mode");
    const auto edge = bindingAction("speed:edge", 1.0);
    ASSERT_TRUE(edge);
    EXPECT_EQ(std::get<SetSpeed>(*edge).kind, SpeedKind::Edge);
    EXPECT_EQ(std::get<SetSpeed>(*bindingAction("speed:classify", 1.0)).kind, SpeedKind::Classify);
    EXPECT_TRUE(std::get<SetOutsideMode>(*bindingAction("outside_mode:on", 1.0)).outside);
    EXPECT_TRUE(std::holds_alternative<ClearExamples>(*bindingAction("clear_examples", 1.0)));
}

TEST(WorkflowSpeed, ALoadStartsWithTheConfiguredSpeed) {
    Rig rig;
    rig.load();
    ASSERT_EQ(rig.engine.speeds.size(), 1U) << "the new scan hears its speed";
    EXPECT_EQ(rig.engine.speeds[0].kind, SpeedKind::Threshold);
    EXPECT_EQ(rig.status().speed, SpeedKind::Threshold);
    EXPECT_EQ(rig.status().speedInForce, SpeedKind::Threshold);

    Settings s = testSettings();
    s.defaultSpeed = SpeedKind::Edge;
    Rig edge(s);
    edge.load();
    ASSERT_EQ(edge.engine.speeds.size(), 1U);
    EXPECT_EQ(edge.engine.speedKind(), SpeedKind::Edge);
    EXPECT_EQ(edge.status().speed, SpeedKind::Edge);
    EXPECT_FALSE(edge.status().canUndo) << "the load's speed is no edit";
}

TEST(WorkflowSpeed, ARefusedDefaultSpeedLeavesTheThresholdSpeedAndSaysWhy) {
    Settings s = testSettings();
    s.defaultSpeed = SpeedKind::Edge;
    Rig rig(s);
    rig.engine.speedError = "edge speed: not enough GPU memory for the smoothed scan";
    rig.load();
    EXPECT_EQ(rig.status().speed, SpeedKind::Threshold);
    EXPECT_EQ(rig.status().speedInForce, SpeedKind::Threshold);
    EXPECT_EQ(rig.status().message,
              "the threshold speed runs: edge speed: not enough GPU memory for the smoothed scan");
    EXPECT_EQ(rig.engine.misuse(), 0) << rig.engine.lastMisuse();
}

// A speed this GPU computed wrong in the start-up check (Settings::speedsOff, issue 47) never
// reaches the engine: SetSpeed is refused with the check's reason, and the alarm says why.
TEST(WorkflowSpeed, ASpeedOffOnThisGpuIsNeverRun) {
    Settings s = testSettings();
    s.speedsOff = {{SpeedKind::Classify, "gathered features within 75.8"}};
    Rig rig(s);
    EXPECT_EQ(rig.status().speedsOff, std::vector<SpeedKind>{SpeedKind::Classify});
    EXPECT_EQ(rig.status().gpuAlarm,
              "GPU CHECK FAILED. The classify speed is off: this GPU computed it wrong at start-up "
              "(gathered features within 75.8). The threshold speed runs instead.");
    rig.load();
    const Workflow::Outcome classify = rig.act(SetSpeed{SpeedKind::Classify});
    EXPECT_FALSE(classify.accepted);
    EXPECT_EQ(classify.reason, "the classify speed is off: this GPU computed it wrong at start-up");
    EXPECT_TRUE(rig.act(SetSpeed{SpeedKind::Edge}).accepted);
    for (const SpeedChoice& c : rig.engine.speeds) {
        EXPECT_NE(c.kind, SpeedKind::Classify);
    }
    EXPECT_EQ(rig.engine.misuse(), 0) << rig.engine.lastMisuse();

    Settings off = testSettings();
    off.defaultSpeed = SpeedKind::Classify;
    off.speedsOff = {{SpeedKind::Classify, "x"}};
    EXPECT_THROW(Rig{off}, std::invalid_argument) << "the kiosk runs a speed that passed instead";

    // Every speed failed: the threshold speed runs, and the alarm says no mask can be trusted.
    Settings none = testSettings();
    none.speedsOff = {{SpeedKind::Edge, "e"}, {SpeedKind::Classify, "c"}};
    none.defaultSpeedFailed = "12 solver iterations: 40 voxels apart";
    const Rig broken(none);
    EXPECT_EQ(
        broken.status().gpuAlarm,
        "GPU CHECK FAILED. The edge speed is off: this GPU computed it wrong at start-up (e). "
        "The classify speed is off: this GPU computed it wrong at start-up (c). The "
        "threshold speed failed too (12 solver iterations: 40 voxels apart): no mask of "
        "this GPU can be trusted.");
}

TEST(WorkflowSpeed, SpeedAndExamplesChangeWhereParametersDo) {
    const std::vector<std::pair<State, std::string>> states{
        {State::NoScan, "no scan loaded: load one first"},
        {State::Loading, "a scan is loading"},
        {State::Inspect, ""},
        {State::Seeding, ""},
        {State::Evolving, ""},
        {State::Paused, ""},
        {State::Review, "go back to steering to change parameters"},
        {State::Done, "the result is exported: go back to review, or load the next scan"},
        {State::Error, "dismiss the error first"},
    };
    for (const auto& [state, why] : states) {
        SCOPED_TRACE(std::string(stateName(state)));
        Rig rig;
        rig.driveTo(state);
        const std::size_t calls = rig.engine.speeds.size();
        const Workflow::Outcome speed = rig.act(SetSpeed{SpeedKind::Edge});
        const Workflow::Outcome mark = rig.act(MarkOutside{kOutside, 2.0});
        const Workflow::Outcome clear = rig.act(ClearExamples{});
        EXPECT_EQ(speed.accepted, why.empty());
        EXPECT_EQ(speed.reason, why);
        EXPECT_EQ(mark.accepted, why.empty());
        EXPECT_EQ(mark.reason, why);
        EXPECT_EQ(clear.accepted, why.empty());
        EXPECT_EQ(clear.reason, why);
        EXPECT_EQ(rig.state(), state) << "a speed change moves no state";
        if (why.empty()) {
            EXPECT_EQ(rig.engine.speeds.size(), calls + 1) << "edge, once";
            EXPECT_EQ(rig.engine.speedKind(), SpeedKind::Edge);
            EXPECT_EQ(rig.status().speed, SpeedKind::Edge);
            EXPECT_TRUE(rig.status().outsideExamples.empty()) << "cleared";
        } else {
            EXPECT_EQ(rig.engine.speeds.size(), calls);
            EXPECT_TRUE(rig.status().outsideExamples.empty());
        }
        EXPECT_EQ(rig.engine.misuse(), 0) << rig.engine.lastMisuse();
    }
}

TEST(WorkflowSpeed, ASpeedChangeClearsConvergenceAndRunsLive) {
    Rig rig;
    rig.driveTo(State::Evolving);
    rig.engine.convergeAfter = 5;
    rig.wf->evolve(10);
    ASSERT_EQ(rig.state(), State::Paused);
    ASSERT_TRUE(rig.status().converged);
    ASSERT_TRUE(rig.act(SetSpeed{SpeedKind::Edge}).accepted);
    EXPECT_FALSE(rig.status().converged);
    ASSERT_TRUE(rig.act(model::Run{}).accepted);
    ASSERT_TRUE(rig.act(SetSpeed{SpeedKind::Threshold}).accepted);
    EXPECT_EQ(rig.state(), State::Evolving) << "the front goes on under the new speed";
    EXPECT_EQ(rig.engine.speedKind(), SpeedKind::Threshold);
    const std::size_t calls = rig.engine.speeds.size();
    ASSERT_TRUE(rig.act(SetSpeed{SpeedKind::Threshold}).accepted) << "a second press is no error";
    EXPECT_EQ(rig.engine.speeds.size(), calls);
    EXPECT_FALSE(rig.act(SetSpeed{static_cast<SpeedKind>(7)}).accepted);
}

TEST(WorkflowSpeed, ClassifyWaitsForAnExampleOfEachKind) {
    Rig rig;
    rig.load();
    ASSERT_TRUE(rig.act(SetSpeed{SpeedKind::Edge}).accepted);
    const Workflow::Outcome classify = rig.act(SetSpeed{SpeedKind::Classify});
    ASSERT_TRUE(classify.accepted) << classify.reason;
    EXPECT_EQ(rig.status().speed, SpeedKind::Classify);
    EXPECT_EQ(rig.status().speedInForce, SpeedKind::Edge) << "the speed before goes on";
    EXPECT_EQ(rig.engine.speedKind(), SpeedKind::Edge);
    EXPECT_NE(rig.status().message.find("classify needs an inside example (a probe or a seed) "
                                        "and an outside example; the edge speed runs until then"),
              std::string::npos)
        << rig.status().message;

    ASSERT_TRUE(rig.act(Probe{kInside, 3.0}).accepted);
    EXPECT_EQ(rig.status().insideExamples.size(), 1U);
    EXPECT_EQ(rig.engine.speedKind(), SpeedKind::Edge) << "no outside example yet";

    const std::size_t calls = rig.engine.speeds.size();
    ASSERT_TRUE(rig.act(MarkOutside{kOutside, 2.0}).accepted);
    ASSERT_EQ(rig.engine.speeds.size(), calls + 1);
    const SpeedChoice& trained = rig.engine.speeds.back();
    EXPECT_EQ(trained.kind, SpeedKind::Classify);
    ASSERT_EQ(trained.inside.size(), 1U);
    ASSERT_EQ(trained.outside.size(), 1U);
    EXPECT_EQ(trained.inside[0].centre, glm::vec3(kInside));
    EXPECT_EQ(trained.outside[0].centre, glm::vec3(kOutside));
    // 2 mm on 1 x 1 x 2 mm voxels: 2 voxels along the finest axis (model::Sphere).
    EXPECT_NEAR(trained.outside[0].radius, 2.0, 1e-6);
    EXPECT_EQ(rig.status().speedInForce, SpeedKind::Classify);
    EXPECT_TRUE(trained.withinWindow) << "bounded by the window by default";
    EXPECT_EQ(trained.placeReach, 3.0) << "the examples decide near them by default";

    // Every further example retrains.
    ASSERT_TRUE(rig.act(Probe{{10.0, 6.0, 4.0}, 3.0}).accepted);
    EXPECT_EQ(rig.engine.speeds.size(), calls + 2);
    EXPECT_EQ(rig.engine.speeds.back().inside.size(), 2U);

    // Cleared, the classifier has nothing to learn from: the speed before classify runs.
    ASSERT_TRUE(rig.act(ClearExamples{}).accepted);
    EXPECT_EQ(rig.engine.speedKind(), SpeedKind::Edge);
    EXPECT_EQ(rig.status().speed, SpeedKind::Classify);
    EXPECT_EQ(rig.status().speedInForce, SpeedKind::Edge);
    EXPECT_NE(rig.status().message.find("examples cleared"), std::string::npos);
    EXPECT_FALSE(rig.act(ClearExamples{}).accepted);
    EXPECT_EQ(rig.status().message, "no examples to clear");
    EXPECT_EQ(rig.engine.misuse(), 0) << rig.engine.lastMisuse();
}

TEST(WorkflowSpeed, TheWindowAndThePlaceReachAreTheSettings) {
    Settings s = testSettings();
    s.classifyWithinWindow = false;
    s.classifyPlaceReach = 1.5;
    Rig rig(s);
    rig.load();
    ASSERT_TRUE(rig.act(SetSpeed{SpeedKind::Classify}).accepted);
    EXPECT_FALSE(rig.engine.speeds.back().withinWindow) << "the threshold, waiting";
    ASSERT_TRUE(rig.act(Probe{kInside, 3.0}).accepted);
    ASSERT_TRUE(rig.act(MarkOutside{kOutside, 2.0}).accepted);
    ASSERT_EQ(rig.engine.speedKind(), SpeedKind::Classify);
    EXPECT_FALSE(rig.engine.speeds.back().withinWindow) << "the forest's answer alone";
    EXPECT_EQ(rig.engine.speeds.back().placeReach, 1.5);
}

TEST(WorkflowSpeed, EdgeAndThresholdIgnoreExamples) {
    Rig rig;
    rig.load();
    ASSERT_TRUE(rig.act(SetSpeed{SpeedKind::Edge}).accepted);
    const std::size_t calls = rig.engine.speeds.size();
    ASSERT_TRUE(rig.act(Probe{kInside, 3.0}).accepted);
    ASSERT_TRUE(rig.act(MarkOutside{kOutside, 0.0}).accepted);
    EXPECT_EQ(rig.engine.speeds.size(), calls) << "the edge speed learns nothing";
    EXPECT_EQ(rig.status().outsideExamples.size(), 1U) << "kept for classify";
    // No radius: the probe's (5 mm, 5 voxels along the finest axis).
    EXPECT_NEAR(rig.status().outsideExamples[0].radius, 5.0, 1e-6);
    ASSERT_TRUE(rig.act(SetSpeed{SpeedKind::Classify}).accepted);
    EXPECT_EQ(rig.engine.speedKind(), SpeedKind::Classify) << "the examples were there";
    EXPECT_TRUE(rig.status().message.empty()) << rig.status().message;
}

TEST(WorkflowSpeed, TheNewestExamplesOfEachKindCount) {
    Rig rig;
    rig.load();
    ASSERT_TRUE(rig.act(SetSpeed{SpeedKind::Classify}).accepted);
    for (int i = 0; i < static_cast<int>(kMaxExamples) + 2; ++i) {
        ASSERT_TRUE(rig.act(Probe{{2.0 + i, 6.0, 4.0}, 2.0}).accepted);
        ASSERT_TRUE(rig.act(MarkOutside{{2.0 + i, 1.0, 1.0}, 2.0}).accepted);
    }
    ASSERT_EQ(rig.status().insideExamples.size(), kMaxExamples);
    ASSERT_EQ(rig.status().outsideExamples.size(), kMaxExamples);
    EXPECT_EQ(rig.status().insideExamples.front().centre.x, 4.0F) << "the oldest went";
    EXPECT_EQ(rig.status().insideExamples.back().centre.x, 3.0F + kMaxExamples);
    EXPECT_EQ(rig.status().outsideExamples.front().centre.x, 4.0F);
    const SpeedChoice& last = rig.engine.speeds.back();
    EXPECT_EQ(last.inside.size(), kMaxExamples);
    EXPECT_EQ(last.outside.size(), kMaxExamples);
    EXPECT_FALSE(rig.act(MarkOutside{{99.0, 1.0, 1.0}, 2.0}).accepted);
    EXPECT_EQ(rig.status().message, "outside example outside the scan");
    EXPECT_FALSE(rig.act(MarkOutside{{1.0, NAN, 1.0}, 2.0}).accepted);
    // A huge radius is bounded by the scan's diagonal (the solver's limit on a sphere).
    ASSERT_TRUE(rig.act(MarkOutside{{1.0, 1.0, 1.0}, 1e308}).accepted);
    EXPECT_FLOAT_EQ(rig.status().outsideExamples.back().radius,
                    static_cast<float>(glm::length(glm::dvec3(16.0, 12.0, 8.0))));
    EXPECT_EQ(rig.engine.misuse(), 0) << rig.engine.lastMisuse();
}

TEST(WorkflowSpeed, UndoAndRedoTheSpeedAndTheExamples) {
    Rig rig;
    rig.driveTo(State::Paused);
    ASSERT_TRUE(rig.act(SetSpeed{SpeedKind::Edge}).accepted);
    ASSERT_TRUE(rig.act(Undo{}).accepted);
    EXPECT_EQ(rig.status().speed, SpeedKind::Threshold);
    EXPECT_EQ(rig.engine.speedKind(), SpeedKind::Threshold);
    ASSERT_TRUE(rig.act(Redo{}).accepted);
    EXPECT_EQ(rig.status().speed, SpeedKind::Edge);
    EXPECT_EQ(rig.engine.speedKind(), SpeedKind::Edge);

    ASSERT_TRUE(rig.act(SetSpeed{SpeedKind::Classify}).accepted);
    ASSERT_TRUE(rig.act(Probe{kInside, 3.0}).accepted);
    ASSERT_TRUE(rig.act(MarkOutside{kOutside, 2.0}).accepted);
    ASSERT_EQ(rig.engine.speedKind(), SpeedKind::Classify);
    ASSERT_TRUE(rig.act(model::Run{}).accepted);
    // Undo of the outside mark: classify waits again, the edge speed runs.
    ASSERT_TRUE(rig.act(Undo{}).accepted);
    EXPECT_EQ(rig.state(), State::Paused);
    EXPECT_TRUE(rig.status().outsideExamples.empty());
    EXPECT_EQ(rig.status().insideExamples.size(), 2U) << "the seed's and the probe's";
    EXPECT_EQ(rig.engine.speedKind(), SpeedKind::Edge);
    EXPECT_EQ(rig.status().speedInForce, SpeedKind::Edge);
    // Undo of the probe takes its inside example with its T and eps; the seed's stays.
    ASSERT_TRUE(rig.act(Undo{}).accepted);
    EXPECT_EQ(rig.status().insideExamples.size(), 1U);
    ASSERT_TRUE(rig.act(Undo{}).accepted);
    EXPECT_EQ(rig.status().speed, SpeedKind::Edge);
    // Redone, the classifier is trained on the same examples again.
    for (int i = 0; i < 3; ++i) {
        ASSERT_TRUE(rig.act(Redo{}).accepted);
    }
    EXPECT_EQ(rig.engine.speedKind(), SpeedKind::Classify);
    EXPECT_EQ(rig.engine.speeds.back().outside.size(), 1U);
    EXPECT_FALSE(rig.status().canRedo);
    EXPECT_EQ(rig.engine.misuse(), 0) << rig.engine.lastMisuse();
}

// A seed lies in the structure: an inside example, placed and taken back with the seed.
TEST(WorkflowSpeed, ASeedIsAnInsideExampleThatUndoTakesBack) {
    Rig rig;
    rig.load();
    ASSERT_TRUE(rig.act(SetSpeed{SpeedKind::Classify}).accepted);
    ASSERT_TRUE(rig.act(MarkOutside{kOutside, 2.0}).accepted);
    EXPECT_NE(rig.engine.speedKind(), SpeedKind::Classify) << "no inside example yet";
    ASSERT_TRUE(rig.act(AddSeed{kInside, 2.0}).accepted);
    ASSERT_EQ(rig.status().insideExamples.size(), 1U);
    EXPECT_EQ(glm::dvec3(rig.status().insideExamples[0].centre), kInside);
    EXPECT_EQ(rig.status().insideExamples[0].radius, 2.0F);
    EXPECT_EQ(rig.engine.speedKind(), SpeedKind::Classify);
    EXPECT_EQ(rig.engine.speeds.back().inside.size(), 1U);
    EXPECT_EQ(rig.status().seeds, 1);

    ASSERT_TRUE(rig.act(Undo{}).accepted);
    EXPECT_EQ(rig.status().seeds, 0);
    EXPECT_TRUE(rig.status().insideExamples.empty());
    EXPECT_NE(rig.engine.speedKind(), SpeedKind::Classify) << "classify waits again";
    ASSERT_TRUE(rig.act(Redo{}).accepted);
    EXPECT_EQ(rig.status().seeds, 1);
    EXPECT_EQ(rig.status().insideExamples.size(), 1U);
    EXPECT_EQ(rig.engine.speedKind(), SpeedKind::Classify);
    // An eraser is no example.
    ASSERT_TRUE(rig.act(Erase{kOutside, 1.0}).accepted);
    EXPECT_EQ(rig.status().insideExamples.size(), 1U);
    EXPECT_EQ(rig.engine.misuse(), 0) << rig.engine.lastMisuse();
}

// A refused speed neither blocks the seed nor its undo: the surface follows, the speed stays
// and the notice says so.
TEST(WorkflowSpeed, ARefusedSpeedLeavesTheSeedAndItsUndoStanding) {
    Rig rig;
    rig.load();
    ASSERT_TRUE(rig.act(SetSpeed{SpeedKind::Edge}).accepted);
    ASSERT_TRUE(rig.act(SetSpeed{SpeedKind::Classify}).accepted); // edge runs until examples
    ASSERT_TRUE(rig.act(MarkOutside{kOutside, 2.0}).accepted);
    rig.engine.speedError = "the GPU is busy";
    ASSERT_TRUE(rig.act(AddSeed{kInside, 2.0}).accepted);
    EXPECT_EQ(rig.status().seeds, 1);
    EXPECT_EQ(rig.engine.speedKind(), SpeedKind::Edge);
    EXPECT_NE(rig.status().message.find("the surface changed, but the speed stayed: "
                                        "the GPU is busy"),
              std::string::npos)
        << rig.status().message;
    EXPECT_TRUE(rig.status().insideExamples.empty()) << "the refused example is not kept";

    rig.engine.speedError.clear();
    ASSERT_TRUE(rig.act(AddSeed{kInside + glm::dvec3(1.0, 0.0, 0.0), 2.0}).accepted);
    ASSERT_EQ(rig.engine.speedKind(), SpeedKind::Classify);
    rig.engine.speedError = "the GPU is busy";
    ASSERT_TRUE(rig.act(Undo{}).accepted); // back to edge, which the engine refuses now
    EXPECT_EQ(rig.status().seeds, 1);
    EXPECT_EQ(rig.engine.speedKind(), SpeedKind::Classify);
    EXPECT_NE(rig.status().message.find("the surface changed, but the speed stayed"),
              std::string::npos)
        << rig.status().message;
    EXPECT_TRUE(rig.status().canRedo);
    EXPECT_EQ(rig.engine.misuse(), 0) << rig.engine.lastMisuse();
}

TEST(WorkflowSpeed, ARefusalKeepsThePreviousSpeedAndSaysWhy) {
    Rig rig;
    rig.driveTo(State::Paused);
    const std::size_t undo = rig.wf->undoDepth();
    rig.engine.speedError = "edge speed: not enough GPU memory\nfor the smoothed scan";
    const Workflow::Outcome out = rig.act(SetSpeed{SpeedKind::Edge});
    EXPECT_FALSE(out.accepted);
    EXPECT_EQ(out.reason, "edge speed: not enough GPU memory");
    EXPECT_EQ(rig.status().message, out.reason);
    EXPECT_EQ(rig.status().speed, SpeedKind::Threshold);
    EXPECT_EQ(rig.status().speedInForce, SpeedKind::Threshold);
    EXPECT_EQ(rig.engine.speedKind(), SpeedKind::Threshold);
    EXPECT_EQ(rig.wf->undoDepth(), undo) << "nothing to undo";
    EXPECT_EQ(rig.state(), State::Paused);

    // A classifier that cannot be trained keeps the examples it had.
    rig.engine.speedError.clear();
    ASSERT_TRUE(rig.act(SetSpeed{SpeedKind::Classify}).accepted);
    ASSERT_TRUE(rig.act(Probe{kInside, 3.0}).accepted);
    rig.engine.speedError = "classify: the examples hold no voxels";
    const Workflow::Outcome mark = rig.act(MarkOutside{kOutside, 2.0});
    EXPECT_FALSE(mark.accepted);
    EXPECT_EQ(mark.reason, "classify: the examples hold no voxels");
    EXPECT_TRUE(rig.status().outsideExamples.empty());
    EXPECT_EQ(rig.status().speedInForce, SpeedKind::Threshold);
    EXPECT_EQ(rig.engine.misuse(), 0) << rig.engine.lastMisuse();
}

TEST(WorkflowSpeed, OutsideModeAndEraseModeExcludeEachOther) {
    Rig rig;
    EXPECT_FALSE(rig.act(SetOutsideMode{true}).accepted);
    rig.driveTo(State::Seeding);
    const std::size_t depth = rig.wf->undoDepth();
    ASSERT_TRUE(rig.act(SetEraseMode{true}).accepted);
    ASSERT_TRUE(rig.act(SetOutsideMode{true}).accepted);
    EXPECT_TRUE(rig.status().outsideMode);
    EXPECT_FALSE(rig.status().eraseMode);
    ASSERT_TRUE(rig.act(SetEraseMode{true}).accepted);
    EXPECT_FALSE(rig.status().outsideMode);
    ASSERT_TRUE(rig.act(SetOutsideMode{true}).accepted);
    EXPECT_EQ(rig.wf->undoDepth(), depth) << "a mode is no edit";
}

TEST(WorkflowSpeed, ANewScanForgetsTheExamples) {
    Rig rig;
    rig.load();
    ASSERT_TRUE(rig.act(SetSpeed{SpeedKind::Classify}).accepted);
    ASSERT_TRUE(rig.act(Probe{kInside, 3.0}).accepted);
    ASSERT_TRUE(rig.act(MarkOutside{kOutside, 2.0}).accepted);
    ASSERT_TRUE(rig.act(SetOutsideMode{true}).accepted);
    rig.load(); // no level set: nothing unexported
    EXPECT_TRUE(rig.status().insideExamples.empty());
    EXPECT_TRUE(rig.status().outsideExamples.empty());
    EXPECT_FALSE(rig.status().outsideMode);
    EXPECT_EQ(rig.status().speed, SpeedKind::Threshold);
    EXPECT_EQ(rig.engine.speeds.back().kind, SpeedKind::Threshold);
    EXPECT_EQ(rig.engine.misuse(), 0) << rig.engine.lastMisuse();
}

TEST(WorkflowSpeed, TheAuditLogRecordsTheSpeed) {
    const fs::path dir = fs::path(testing::TempDir()) / "workflow-speed-audit";
    fs::remove_all(dir);
    const fs::path path = dir / "audit.jsonl";
    {
        AuditLog log(path, fixedTime);
        Rig rig(testSettings(), &log);
        rig.load();
        ASSERT_TRUE(rig.act(SetSpeed{SpeedKind::Classify}).accepted);
        ASSERT_TRUE(rig.act(Probe{kInside, 3.0}).accepted);
        ASSERT_TRUE(rig.act(MarkOutside{kOutside, 2.0}).accepted);
        rig.engine.speedError = "edge speed: no GPU memory";
        ASSERT_FALSE(rig.act(SetSpeed{SpeedKind::Edge}).accepted);
    }
    std::vector<nlohmann::json> lines;
    std::ifstream in(path);
    std::string line;
    while (std::getline(in, line)) {
        lines.push_back(nlohmann::json::parse(line));
    }
    std::vector<nlohmann::json> speeds;
    nlohmann::json mark;
    nlohmann::json probe;
    for (const nlohmann::json& j : lines) {
        const std::string action = j.value("action", "");
        if (action == "set_speed") {
            speeds.push_back(j);
        } else if (action == "mark_outside") {
            mark = j;
        } else if (action == "probe") {
            probe = j;
        }
    }
    ASSERT_EQ(speeds.size(), 2U);
    EXPECT_EQ(speeds[0]["values"]["speed"], "classify");
    EXPECT_EQ(speeds[0]["result"]["speed"], "classify");
    EXPECT_EQ(speeds[0]["result"]["speed_in_force"], "threshold");
    EXPECT_EQ(speeds[0]["result"]["inside_examples"], 0);
    EXPECT_EQ(probe["result"]["inside_examples"], 1);
    EXPECT_EQ(mark["values"]["voxel"], nlohmann::json::array({1.0, 1.0, 1.0}));
    EXPECT_EQ(mark["values"]["radius_mm"], 2.0);
    EXPECT_EQ(mark["result"]["speed_in_force"], "classify");
    EXPECT_EQ(mark["result"]["outside_examples"], 1);
    EXPECT_EQ(speeds[1]["accepted"], false);
    EXPECT_EQ(speeds[1]["reason"], "edge speed: no GPU memory");
    EXPECT_EQ(speeds[1]["values"]["speed"], "edge");
}

} // namespace
} // namespace steerseg::test
