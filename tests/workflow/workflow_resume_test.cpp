#include "support/workflow_rig.hpp"
#include "workflow/param_ranges.hpp"

#include <gtest/gtest.h>

namespace steerseg::test {
namespace {

using namespace workflow;

using namespace model;

RestoredSession restored(State state) {
    RestoredSession r;
    r.params.values[indexOf(Param::T)] = 120.0;
    r.params.values[indexOf(Param::Eps)] = 60.0;
    r.params.values[indexOf(Param::Alpha)] = 0.5;
    r.params.values[indexOf(Param::Radius)] = 2.5;
    r.params.preset = "CT soft tissue";
    r.seeds = 2;
    r.erasures = 1;
    r.state = state;
    r.notice = "resumed the session saved 13:01:40";
    return r;
}

// The kiosk puts the autosave's level set into the engine, then hands the rest to the workflow.
TEST(WorkflowResume, ARunComesBackPausedWithItsParametersAndCounts) {
    Rig rig;
    rig.load();
    rig.engine.addSeed({{8.0, 6.0, 4.0}, 2.0});
    const auto o = rig.wf->restoreSession(restored(State::Evolving));
    ASSERT_TRUE(o.accepted) << o.reason;
    EXPECT_EQ(rig.state(), State::Paused);
    const Status& st = rig.status();
    EXPECT_EQ(st.params.T, 120.0F);
    EXPECT_EQ(st.params.eps, 60.0F);
    EXPECT_EQ(st.params.alpha, 0.5F);
    EXPECT_EQ(st.radius, 2.5);
    EXPECT_EQ(st.preset, "CT soft tissue");
    EXPECT_EQ(rig.engine.params().T, 120.0F); // the engine heard them
    EXPECT_EQ(st.seeds, 2);
    EXPECT_EQ(st.erasures, 1);
    EXPECT_TRUE(st.hasLevelSet);
    EXPECT_FALSE(st.canUndo);
    EXPECT_EQ(st.message, "resumed the session saved 13:01:40");
    // The resumed surface was never exported: a new load must not drop it silently.
    EXPECT_FALSE(rig.act(LoadScan{"other.nii.gz"}).accepted);
    EXPECT_TRUE(rig.act(model::Run{}).accepted);
}

TEST(WorkflowResume, TheSpeedAndItsExamplesComeBack) {
    Rig rig;
    rig.load();
    rig.engine.addSeed({{8.0, 6.0, 4.0}, 2.0});
    RestoredSession r = restored(State::Paused);
    r.params.speed = {
        model::SpeedKind::Classify, {{{8.0F, 6.0F, 4.0F}, 2.0F}}, {{{1.0F, 1.0F, 1.0F}, 1.0F}}};
    const auto o = rig.wf->restoreSession(r);
    ASSERT_TRUE(o.accepted) << o.reason;
    EXPECT_EQ(rig.status().speed, model::SpeedKind::Classify);
    EXPECT_EQ(rig.status().speedInForce, model::SpeedKind::Classify);
    EXPECT_EQ(rig.engine.speedKind(), model::SpeedKind::Classify) << "retrained";
    EXPECT_EQ(rig.status().outsideExamples.size(), 1U);
    EXPECT_EQ(rig.status().message, "resumed the session saved 13:01:40");
}

// A resumed run must not undo the corrections that stuck: their barriers come back in order.
TEST(WorkflowResume, TheCorrectionsBarriersComeBack) {
    Rig rig;
    rig.load();
    rig.engine.addSeed({{8.0, 6.0, 4.0}, 2.0});
    RestoredSession r = restored(State::Paused);
    r.barriers = {{{{10.0F, 6.0F, 4.0F}, 1.0F}, false}, {{{6.0F, 6.0F, 4.0F}, 1.5F}, true}};
    const auto o = rig.wf->restoreSession(r);
    ASSERT_TRUE(o.accepted) << o.reason;
    EXPECT_EQ(rig.engine.barrierList(), r.barriers);
    EXPECT_EQ(rig.status().message, "resumed the session saved 13:01:40");
    ASSERT_TRUE(rig.act(model::Restart{}).accepted);
    EXPECT_EQ(rig.engine.barriers(), 0);
}

TEST(WorkflowResume, ASpeedTheEngineRefusesLeavesTheThresholdSpeed) {
    Rig rig;
    rig.load();
    rig.engine.addSeed({{8.0, 6.0, 4.0}, 2.0});
    RestoredSession r = restored(State::Paused);
    r.params.speed.kind = model::SpeedKind::Edge;
    rig.engine.speedError = "edge speed: not enough GPU memory";
    const auto o = rig.wf->restoreSession(r);
    ASSERT_TRUE(o.accepted) << o.reason;
    EXPECT_EQ(rig.state(), State::Paused) << "the level set is back all the same";
    EXPECT_EQ(rig.status().speed, model::SpeedKind::Threshold);
    EXPECT_EQ(rig.status().params.T, 120.0F);
    EXPECT_EQ(rig.status().message, "the threshold speed runs: edge speed: not enough GPU memory");
}

TEST(WorkflowResume, StatesComeBackWhereTheyCan) {
    const struct {
        State saved;
        bool levelSet;
        State expected;
    } cases[] = {
        {State::Inspect, false, State::Inspect},  {State::Seeding, false, State::Seeding},
        {State::Seeding, true, State::Seeding},   {State::Review, true, State::Review},
        {State::Review, false, State::Seeding},   {State::Paused, true, State::Paused},
        {State::Evolving, false, State::Seeding}, {State::Error, true, State::Paused},
        {State::Exporting, true, State::Paused},
    };
    for (const auto& c : cases) {
        Rig rig;
        rig.load();
        if (c.levelSet) {
            rig.engine.addSeed({{8.0, 6.0, 4.0}, 2.0});
        }
        ASSERT_TRUE(rig.wf->restoreSession(restored(c.saved)).accepted);
        EXPECT_EQ(rig.state(), c.expected) << stateName(c.saved) << " " << c.levelSet;
    }
}

TEST(WorkflowResume, OnlyRightAfterTheScanLoaded) {
    Rig rig;
    EXPECT_FALSE(rig.wf->restoreSession(restored(State::Paused)).accepted); // no scan
    rig.load();
    rig.seed();
    ASSERT_EQ(rig.state(), State::Seeding);
    const auto o = rig.wf->restoreSession(restored(State::Paused));
    EXPECT_FALSE(o.accepted);
    EXPECT_NE(o.reason.find("seeding"), std::string::npos) << o.reason;
    EXPECT_EQ(rig.status().seeds, 1); // nothing changed
}

} // namespace
} // namespace steerseg::test
