#include "support/workflow_rig.hpp"

#include <gtest/gtest.h>

namespace steerseg::test {
namespace {

using namespace workflow;

using namespace model;

TEST(WorkflowUndo, SeedsAndErasuresUndoAndRedoExactly) {
    Rig rig;
    rig.load();
    rig.seed({4.0, 4.0, 4.0}, 2.0);
    const std::size_t one = rig.engine.insideVoxels();
    rig.seed({11.0, 6.0, 4.0}, 2.0);
    const std::size_t two = rig.engine.insideVoxels();
    ASSERT_TRUE(rig.act(Erase{{4.0, 4.0, 4.0}, 1.0}).accepted);
    const std::size_t erased = rig.engine.insideVoxels();
    EXPECT_GT(two, one);
    EXPECT_LT(erased, two);
    EXPECT_EQ(rig.status().seeds, 2);
    EXPECT_EQ(rig.status().erasures, 1);

    ASSERT_TRUE(rig.act(Undo{}).accepted);
    EXPECT_EQ(rig.engine.insideVoxels(), two);
    EXPECT_EQ(rig.status().erasures, 0);
    ASSERT_TRUE(rig.act(Undo{}).accepted);
    EXPECT_EQ(rig.engine.insideVoxels(), one);
    ASSERT_TRUE(rig.act(Undo{}).accepted);
    EXPECT_EQ(rig.engine.insideVoxels(), 0U);
    EXPECT_FALSE(rig.status().hasLevelSet);
    EXPECT_EQ(rig.status().seeds, 0);
    EXPECT_FALSE(rig.status().canUndo);
    EXPECT_TRUE(rig.status().canRedo);
    EXPECT_FALSE(rig.act(Undo{}).accepted);

    ASSERT_TRUE(rig.act(Redo{}).accepted);
    ASSERT_TRUE(rig.act(Redo{}).accepted);
    ASSERT_TRUE(rig.act(Redo{}).accepted);
    EXPECT_EQ(rig.engine.insideVoxels(), erased);
    EXPECT_EQ(rig.status().seeds, 2);
    EXPECT_EQ(rig.status().erasures, 1);
    EXPECT_FALSE(rig.status().canRedo);
    EXPECT_EQ(rig.engine.misuse(), 0) << rig.engine.lastMisuse();
}

TEST(WorkflowUndo, SnapshotsAreFreedByNewEditsEvictionAndLoads) {
    Rig rig; // maxUndo 8
    rig.load();
    rig.seed();
    // The first seed's before is the empty level set: one snapshot (after).
    EXPECT_EQ(rig.engine.liveSnapshots(), 1U);
    rig.seed({3.0, 3.0, 3.0}, 1.0);
    EXPECT_EQ(rig.engine.liveSnapshots(), 3U);
    ASSERT_TRUE(rig.act(Undo{}).accepted);
    EXPECT_EQ(rig.engine.liveSnapshots(), 3U); // the redo side keeps its pair
    rig.seed({12.0, 3.0, 3.0}, 1.0);           // a new edit: the redo pair is freed
    EXPECT_EQ(rig.engine.liveSnapshots(), 3U);
    EXPECT_FALSE(rig.status().canRedo);
    for (int i = 0; i < 20; ++i) {
        rig.seed({static_cast<double>(i % 16), 5.0, 5.0}, 1.0);
    }
    EXPECT_EQ(rig.wf->undoDepth(), 8U);
    EXPECT_EQ(rig.engine.liveSnapshots(), 16U);
    EXPECT_EQ(rig.engine.liveSnapshots(), rig.wf->heldSnapshots());
    // A restart keeps the level set it cleared (one snapshot), not the empty one.
    ASSERT_TRUE(rig.act(Restart{}).accepted);
    EXPECT_EQ(rig.wf->undoDepth(), 8U);
    EXPECT_EQ(rig.engine.liveSnapshots(), 15U);
    ASSERT_TRUE(rig.act(Undo{}).accepted);
    EXPECT_TRUE(rig.status().hasLevelSet);
    EXPECT_EQ(rig.status().seeds, 22);
    ASSERT_TRUE(rig.act(Restart{}).accepted);
    // A new scan frees everything.
    ASSERT_TRUE(rig.act(LoadScan{"next.nii"}).accepted);
    EXPECT_EQ(rig.engine.liveSnapshots(), 0U);
    EXPECT_EQ(rig.wf->undoDepth(), 0U);
    EXPECT_EQ(rig.engine.misuse(), 0) << rig.engine.lastMisuse();
}

TEST(WorkflowUndo, DestroyingTheWorkflowFreesItsSnapshots) {
    Rig rig;
    rig.load();
    rig.seed();
    rig.seed({2.0, 2.0, 2.0}, 1.0);
    EXPECT_EQ(rig.engine.liveSnapshots(), 3U);
    rig.wf.reset();
    EXPECT_EQ(rig.engine.liveSnapshots(), 0U);
}

TEST(WorkflowUndo, ParameterChangesCoalescePerParameter) {
    Rig rig;
    rig.load();
    const float t0 = rig.status().params.T;
    const float e0 = rig.status().params.eps;
    for (int i = 0; i < 5; ++i) {
        ASSERT_TRUE(rig.act(NudgeParam{Param::T, 1.0}).accepted);
    }
    ASSERT_TRUE(rig.act(SetParam{Param::T, 100.0}).accepted);
    EXPECT_EQ(rig.wf->undoDepth(), 1U); // one knob turn, one entry
    ASSERT_TRUE(rig.act(NudgeParam{Param::Eps, 3.0}).accepted);
    ASSERT_TRUE(rig.act(NudgeParam{Param::T, 1.0}).accepted);
    EXPECT_EQ(rig.wf->undoDepth(), 3U);
    EXPECT_EQ(rig.status().params.T, 102.0F);

    ASSERT_TRUE(rig.act(Undo{}).accepted);
    EXPECT_EQ(rig.status().params.T, 100.0F);
    EXPECT_EQ(rig.engine.params().T, 100.0F); // live in the engine
    ASSERT_TRUE(rig.act(Undo{}).accepted);
    EXPECT_EQ(rig.status().params.eps, e0);
    ASSERT_TRUE(rig.act(Undo{}).accepted);
    EXPECT_EQ(rig.status().params.T, t0);
    ASSERT_TRUE(rig.act(Redo{}).accepted);
    EXPECT_EQ(rig.status().params.T, 100.0F);
    // After an undo, a change starts a new entry rather than merging into an old one.
    ASSERT_TRUE(rig.act(NudgeParam{Param::T, 1.0}).accepted);
    EXPECT_EQ(rig.wf->undoDepth(), 2U);
    EXPECT_FALSE(rig.status().canRedo);
    // A change that clamps to what is already there records nothing.
    ASSERT_TRUE(rig.act(SetParam{Param::Alpha, 1.0}).accepted);
    ASSERT_TRUE(rig.act(SetParam{Param::Radius, 1.0}).accepted);
    const std::size_t depth = rig.wf->undoDepth();
    ASSERT_TRUE(rig.act(SetParam{Param::Radius, -5.0}).accepted);
    EXPECT_EQ(rig.wf->undoDepth(), depth);
    // Turning a knob there and back leaves nothing to undo for it.
    ASSERT_TRUE(rig.act(NudgeParam{Param::Eps, 4.0}).accepted);
    ASSERT_TRUE(rig.act(NudgeParam{Param::Eps, -4.0}).accepted);
    EXPECT_EQ(rig.wf->undoDepth(), depth);
}

TEST(WorkflowUndo, UndoWhileEvolvingPausesFirst) {
    Rig rig;
    rig.driveTo(State::Evolving);
    rig.wf->evolve(4);
    rig.seed({2.0, 2.0, 2.0}, 1.0);
    ASSERT_EQ(rig.state(), State::Evolving);
    ASSERT_TRUE(rig.act(Undo{}).accepted);
    EXPECT_EQ(rig.state(), State::Paused);
    EXPECT_FALSE(rig.engine.inside({2, 2, 2}));
    EXPECT_EQ(rig.status().iterations, 4); // the snapshot kept the evolution before the seed
    EXPECT_EQ(rig.status().iterations, rig.engine.stats().iterations);
}

TEST(WorkflowUndo, ASnapshotFailureRefusesTheEditAndLeavesTheLevelSet) {
    Rig rig;
    rig.load();
    rig.seed();
    const std::size_t before = rig.engine.insideVoxels();
    rig.engine.snapshotError = "out of GPU memory";
    const Workflow::Outcome out = rig.act(AddSeed{{2.0, 2.0, 2.0}, 1.0});
    EXPECT_FALSE(out.accepted);
    EXPECT_EQ(out.reason, "out of GPU memory");
    EXPECT_EQ(rig.engine.insideVoxels(), before);
    EXPECT_EQ(rig.status().seeds, 1);
    EXPECT_EQ(rig.engine.liveSnapshots(), rig.wf->heldSnapshots());
    rig.engine.snapshotError.clear();
    rig.engine.editError = "sphere edit failed";
    EXPECT_FALSE(rig.act(AddSeed{{2.0, 2.0, 2.0}, 1.0}).accepted);
    EXPECT_EQ(rig.engine.liveSnapshots(), rig.wf->heldSnapshots());
    EXPECT_EQ(rig.engine.misuse(), 0) << rig.engine.lastMisuse();
}

} // namespace
} // namespace steerseg::test
