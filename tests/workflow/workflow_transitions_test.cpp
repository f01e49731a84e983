// Each state against representative actions: accepted or refused (with a reason), and the
// state that follows. Exporting is transient inside handle() and is covered by the export test.
#include "support/workflow_rig.hpp"

#include <cmath>
#include <gtest/gtest.h>
#include <string>
#include <vector>

namespace steerseg::test {
namespace {

using namespace workflow;

using namespace model;

struct Row {
    State from;
    Action action;
    bool accepted;
    State to;
};

std::string describe(const Row& r) {
    return std::string(stateName(r.from)) + " + " + std::string(actionName(r.action));
}

const glm::dvec3 kIn{8.0, 6.0, 4.0};

std::vector<Row> table() {
    const State N = State::NoScan, L = State::Loading, I = State::Inspect, S = State::Seeding,
                E = State::Evolving, P = State::Paused, R = State::Review, D = State::Done,
                X = State::Error;
    const double nan = std::nan("");
    return {
        // No scan: loading and quitting only.
        {N, LoadScan{"a.nii"}, true, L},
        {N, LoadScan{""}, false, N},
        {N, AddSeed{kIn, 2.0}, false, N},
        {N, Run{}, false, N},
        {N, Probe{kIn, 5.0}, false, N},
        {N, SetParam{Param::T, 1.0}, false, N},
        {N, RotateView{10.0, 0.0}, false, N},
        {N, Proceed{}, false, N},
        {N, Back{}, false, N},
        {N, Undo{}, false, N},
        {N, Export{}, false, N},
        {N, Dismiss{}, true, N},
        {N, Quit{}, true, N},
        // Loading: another load replaces it; nothing needs the scan yet.
        {L, LoadScan{"b.nii"}, true, L},
        {L, AddSeed{kIn, 2.0}, false, L},
        {L, PageSlice{SliceAxis::Axial, 1}, false, L},
        {L, Proceed{}, false, L},
        // Inspect.
        {I, Probe{kIn, 5.0}, true, I},
        {I, Probe{{500.0, 6.0, 4.0}, 5.0}, false, I},
        {I, ApplyPreset{"CT bone"}, true, I},
        {I, ApplyPreset{"liver"}, false, I},
        {I, SetParam{Param::Eps, 50.0}, true, I},
        {I, SetParam{Param::Eps, nan}, false, I},
        {I, SetParam{static_cast<Param>(9), 1.0}, false, I},
        {I, NudgeSelected{2.0}, true, I},
        {I, SetWindow{40.0, 400.0}, true, I},
        {I, SetWindow{40.0, 0.0}, false, I},
        {I, AddSeed{kIn, 2.0}, true, S},
        {I, AddSeed{{-1.0, 6.0, 4.0}, 2.0}, false, I},
        {I, AddSeed{{8.0, nan, 4.0}, 2.0}, false, I},
        {I, Erase{kIn, 2.0}, false, I},
        {I, Proceed{}, true, S},
        {I, Run{}, false, I},
        {I, Finish{}, false, I},
        {I, Back{}, false, I},
        {I, Export{}, false, I},
        {I, LoadScan{"b.nii"}, true, L},
        {I, ShowSlices{SliceAxis::Sagittal, SliceAxis::Axial}, true, I},
        {I, ShowSlices{SliceAxis::Axial, SliceAxis::Axial}, false, I},
        {I, ZoomView{-1.0}, false, I},
        // Seeding (with the seed the rig placed).
        {S, AddSeed{kIn, 0.0}, true, S},
        {S, Erase{kIn, 1.0}, true, S},
        {S, Run{}, true, E},
        {S, ToggleRun{}, true, E},
        {S, Proceed{}, true, E},
        {S, Back{}, true, I},
        {S, Finish{}, true, R},
        {S, Pause{}, false, S},
        {S, Restart{}, true, S},
        {S, Undo{}, true, S},
        {S, Redo{}, false, S},
        {S, LoadScan{"b.nii"}, false, S},
        {S, Export{}, false, S},
        {S, Probe{kIn, 5.0}, true, S},
        // Evolving.
        {E, Pause{}, true, P},
        {E, ToggleRun{}, true, P},
        {E, Run{}, true, E},
        {E, SetParam{Param::Alpha, 0.5}, true, E},
        {E, AddSeed{{2.0, 2.0, 2.0}, 1.0}, true, E},
        {E, Undo{}, true, P},
        {E, Finish{}, true, R},
        {E, Proceed{}, true, R},
        {E, Restart{}, true, S},
        {E, Back{}, false, E},
        {E, LoadScan{"b.nii"}, false, E},
        {E, Export{}, false, E},
        {E, Quit{}, true, E},
        // Paused.
        {P, Run{}, true, E},
        {P, ToggleRun{}, true, E},
        {P, Pause{}, true, P},
        {P, Finish{}, true, R},
        {P, Proceed{}, true, R},
        {P, Erase{kIn, 1.0}, true, P},
        {P, Export{"p.nii.gz"}, true, D},
        {P, Resume{}, false, P},
        {P, LoadScan{"b.nii"}, false, P},
        {P, Restart{}, true, S},
        // Review.
        {R, Resume{}, true, P},
        {R, Back{}, true, P},
        {R, Export{"r.nii.gz"}, true, D},
        {R, Proceed{}, true, D},
        {R, AddSeed{kIn, 2.0}, false, R},
        {R, SetParam{Param::T, 3.0}, false, R},
        {R, Undo{}, false, R},
        {R, Run{}, false, R},
        {R, LoadScan{"b.nii"}, false, R},
        {R, RotateView{30.0, 10.0}, true, R},
        {R, Restart{}, true, S},
        // Done: the work is exported, a new scan may come.
        {D, LoadScan{"b.nii"}, true, L},
        {D, Back{}, true, R},
        {D, Proceed{}, false, D},
        {D, AddSeed{kIn, 2.0}, false, D},
        {D, Export{}, false, D},
        {D, Restart{}, true, S},
        {D, PageSlice{SliceAxis::Coronal, -3}, true, D},
        // Error: dismiss (back to the level set), look around, or quit.
        {X, Dismiss{}, true, P},
        {X, Run{}, false, X},
        {X, Proceed{}, false, X},
        {X, AddSeed{kIn, 2.0}, false, X},
        {X, SetParam{Param::T, 3.0}, false, X},
        {X, Undo{}, false, X},
        {X, LoadScan{"b.nii"}, false, X},
        {X, RotateView{5.0, 0.0}, true, X},
        {X, Quit{}, true, X},
    };
}

TEST(WorkflowTransitions, Table) {
    for (const Row& row : table()) {
        Rig rig;
        rig.driveTo(row.from);
        ASSERT_EQ(rig.state(), row.from) << describe(row);
        const Workflow::Outcome out = rig.act(row.action);
        EXPECT_EQ(out.accepted, row.accepted) << describe(row) << ": " << out.reason;
        EXPECT_EQ(rig.state(), row.to) << describe(row) << ": " << out.reason;
        if (out.accepted) {
            EXPECT_TRUE(out.reason.empty()) << describe(row);
        } else {
            EXPECT_FALSE(out.reason.empty()) << describe(row);
            EXPECT_EQ(out.reason.find('\n'), std::string::npos) << describe(row);
        }
        EXPECT_EQ(rig.engine.misuse(), 0) << describe(row) << ": " << rig.engine.lastMisuse();
        EXPECT_EQ(rig.wf->quitRequested(), std::holds_alternative<Quit>(row.action));
    }
}

TEST(WorkflowTransitions, LoadPollsThenInspectsWithRangesAndDefaults) {
    Rig rig;
    rig.engine.loadPolls = 3;
    ASSERT_TRUE(rig.act(LoadScan{"fake.nii.gz"}).accepted);
    for (int i = 0; i < 3; ++i) {
        rig.wf->update();
        EXPECT_EQ(rig.state(), State::Loading);
        EXPECT_GT(rig.status().loadProgress, 0.0);
    }
    rig.wf->update();
    ASSERT_EQ(rig.state(), State::Inspect);
    const Status& s = rig.status();
    EXPECT_EQ(s.scan.name, "fake");
    EXPECT_EQ(s.scan.sliceCount, glm::ivec3(8, 12, 16)); // axial pages k, sagittal i
    EXPECT_EQ(s.ranges[0].min, -1000.0);
    EXPECT_EQ(s.ranges[0].max, 1000.0);
    EXPECT_EQ(s.ranges[0].fineStep, 2.0); // 2000 / 1000
    EXPECT_EQ(s.ranges[1].max, 2000.0);
    EXPECT_EQ(s.ranges[3].max, 4.0); // half of 8 voxels
    EXPECT_EQ(s.params.T, 0.0F);
    EXPECT_GT(s.params.eps, 0.0F);
    EXPECT_EQ(rig.engine.params().eps, s.params.eps); // the engine heard them
    EXPECT_EQ(s.radius, 3.0);
    EXPECT_EQ(s.view.slice, glm::ivec3(-1));
}

TEST(WorkflowTransitions, LoadFailureLeavesNoScanWithTheReadersMessage) {
    Rig rig;
    rig.engine.loadError = "scan.nii: not a NIfTI file (bad magic)";
    ASSERT_TRUE(rig.act(LoadScan{"scan.nii"}).accepted);
    for (int i = 0; i < 5; ++i) {
        rig.wf->update();
    }
    EXPECT_EQ(rig.state(), State::NoScan);
    EXPECT_EQ(rig.status().message, "scan.nii: not a NIfTI file (bad magic)");
    EXPECT_FALSE(rig.act(AddSeed{kIn, 2.0}).accepted);
    rig.engine.loadError.clear();
    rig.load(); // and the next load works
}

TEST(WorkflowTransitions, ConvergencePausesWithANotice) {
    Rig rig;
    rig.driveTo(State::Evolving);
    rig.engine.convergeAfter = 30;
    int total = 0;
    for (int i = 0; i < 10 && rig.state() == State::Evolving; ++i) {
        total += rig.wf->evolve(8).iterations;
    }
    EXPECT_EQ(rig.state(), State::Paused);
    EXPECT_EQ(total, 32);
    EXPECT_TRUE(rig.status().converged);
    EXPECT_EQ(rig.status().iterations, 32);
    EXPECT_NE(rig.status().message.find("converged"), std::string::npos);
    EXPECT_EQ(rig.wf->evolve(8).iterations, 0); // not evolving: nothing happens
}

// The pause names the place and the watch that saw the leak, for the operator and the audit log.
TEST(WorkflowTransitions, ALeakPausesNamingThePlaceAndTheWatchThatSawIt) {
    using model::LeakSign;
    for (const auto& [sign, how] :
         {std::pair{LeakSign::GrowthJump, "its growth jumping after a slowdown"},
          std::pair{LeakSign::RunawayFill, "filling on after it had slowed"}}) {
        Rig rig;
        rig.driveTo(State::Evolving);
        rig.engine.stepLeaks = model::LeakSite{{10, 4, 2}, {14, 8, 4}, 24, sign};
        rig.wf->evolve(8);
        EXPECT_EQ(rig.state(), State::Paused);
        EXPECT_EQ(rig.status().message, std::string("the front broke out near (12, 6, 3), ") + how +
                                            ": erase there, or narrow eps, then run");
    }
}

TEST(WorkflowTransitions, StepFailureIsAnErrorThatDismissReturnsFrom) {
    Rig rig;
    rig.driveTo(State::Error);
    EXPECT_EQ(rig.status().message, "GPU lost");
    // Looking around keeps the error on screen.
    ASSERT_TRUE(rig.act(RotateView{5.0, 0.0}).accepted);
    EXPECT_EQ(rig.status().message, "GPU lost");
    EXPECT_EQ(rig.act(model::Run{}).reason, "dismiss the error first");
    EXPECT_EQ(rig.status().message, "GPU lost");
    ASSERT_TRUE(rig.act(Dismiss{}).accepted);
    EXPECT_EQ(rig.state(), State::Paused);
    EXPECT_TRUE(rig.status().message.empty());
    EXPECT_TRUE(rig.act(model::Run{}).accepted);
}

TEST(WorkflowTransitions, ErasingEverythingWhileEvolvingPauses) {
    Rig rig;
    rig.driveTo(State::Evolving);
    ASSERT_TRUE(rig.act(Erase{{8.0, 6.0, 4.0}, 4.0}).accepted);
    EXPECT_FALSE(rig.status().hasLevelSet);
    EXPECT_EQ(rig.state(), State::Paused);
    EXPECT_FALSE(rig.act(model::Run{}).accepted);
}

TEST(WorkflowTransitions, ViewActionsClampToTheScan) {
    Rig rig;
    rig.load();
    ASSERT_TRUE(rig.act(PageSlice{SliceAxis::Axial, 2}).accepted);
    EXPECT_EQ(rig.status().view.slice[0], 6); // middle of 8, then 2 on
    ASSERT_TRUE(rig.act(PageSlice{SliceAxis::Axial, 1000}).accepted);
    EXPECT_EQ(rig.status().view.slice[0], 7);
    ASSERT_TRUE(rig.act(PageSlice{SliceAxis::Sagittal, -2147483647 - 1}).accepted);
    EXPECT_EQ(rig.status().view.slice[2], 0);
    ASSERT_TRUE(rig.act(SetSlice{SliceAxis::Coronal, 99}).accepted);
    EXPECT_EQ(rig.status().view.slice[1], 11);
    ASSERT_TRUE(rig.act(RotateView{350.0, 100.0}).accepted);
    EXPECT_DOUBLE_EQ(rig.status().view.yawDeg, -10.0);
    EXPECT_DOUBLE_EQ(rig.status().view.pitchDeg, 90.0);
    ASSERT_TRUE(rig.act(ZoomView{1e9}).accepted);
    EXPECT_LE(rig.status().view.zoom, 10.0);
    EXPECT_FALSE(rig.act(RotateView{INFINITY, 0.0}).accepted);
    EXPECT_FALSE(rig.act(PageSlice{static_cast<SliceAxis>(7), 1}).accepted);
    ASSERT_TRUE(rig.act(SetEraseMode{true}).accepted);
    EXPECT_TRUE(rig.status().eraseMode);
    ASSERT_TRUE(rig.act(CycleParam{-1}).accepted);
    EXPECT_EQ(rig.status().selected, Param::Radius);
    ASSERT_TRUE(rig.act(CycleParam{2}).accepted);
    EXPECT_EQ(rig.status().selected, Param::Eps);
}

TEST(WorkflowTransitions, UnexportedWorkBlocksALoadUntilExportedOrRestarted) {
    Rig rig;
    rig.driveTo(State::Paused);
    const Workflow::Outcome out = rig.act(LoadScan{"next.nii"});
    EXPECT_FALSE(out.accepted);
    EXPECT_NE(out.reason.find("export or restart first"), std::string::npos);
    ASSERT_TRUE(rig.act(Restart{}).accepted);
    EXPECT_EQ(rig.state(), State::Seeding);
    EXPECT_TRUE(rig.act(LoadScan{"next.nii"}).accepted);
}

} // namespace
} // namespace steerseg::test
