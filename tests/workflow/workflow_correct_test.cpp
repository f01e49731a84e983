// model::Correct: the operator's correction as the clicks protocol counts it (docs/steering.md).
#include "support/workflow_rig.hpp"

#include <gtest/gtest.h>

namespace steerseg::test {
namespace {

using model::State;

TEST(WorkflowCorrect, TheFirstProbesAndSeedsInOneUndoStepAndRuns) {
    Rig r;
    r.load();
    const float T0 = r.status().params.T;
    // The fake's probe reads -1000 + 2000 * i / 15 with a spread of 10; eps = max(2 x 10, 25).
    ASSERT_TRUE(r.act(model::Correct{{8.0, 6.0, 4.0}, true, 2.0}).accepted);
    EXPECT_EQ(r.state(), State::Evolving);
    EXPECT_NEAR(r.status().params.T, -1000.0 + 2000.0 * 8.0 / 15.0, 1e-3);
    EXPECT_NEAR(r.status().params.eps, 25.0, 1e-6);
    EXPECT_TRUE(r.engine.inside({8, 6, 4}));
    EXPECT_EQ(r.status().seeds, 1);
    EXPECT_EQ(r.status().insideExamples.size(), 2U); // the probe's and the seed's
    // Its sphere holds, as every positive correction's does; its run is the whole surface's.
    ASSERT_EQ(r.engine.barrierList().size(), 1U);
    EXPECT_TRUE(r.engine.barrierList()[0].keep);
    EXPECT_FALSE(r.engine.reach().has_value());
    ASSERT_TRUE(r.act(model::Undo{}).accepted);
    EXPECT_FALSE(r.status().hasLevelSet);
    EXPECT_EQ(r.engine.barriers(), 0);
    EXPECT_EQ(r.status().params.T, T0) << "the probe's T went with the seed";
}

TEST(WorkflowCorrect, TheFirstCannotRemove) {
    Rig r;
    r.load();
    const auto out = r.act(model::Correct{{8.0, 6.0, 4.0}, false, 2.0});
    EXPECT_FALSE(out.accepted);
    EXPECT_NE(out.reason.find("first correction adds"), std::string::npos) << out.reason;
    EXPECT_EQ(r.state(), State::Inspect);
    EXPECT_FALSE(r.act(model::Correct{{80.0, 6.0, 4.0}, true, 2.0}).accepted) << "outside";
}

// A correction's own radius outside the brush's range, as `segment --click` refuses it (a
// typed 1e9 became the largest brush and a run of minutes, issue 51); the brush's own (<= 0)
// and the range's ends are taken.
TEST(WorkflowCorrect, ARadiusBeyondTheBrushsRangeIsNamed) {
    Rig r;
    r.load();
    const workflow::ParamRange range = r.status().ranges[workflow::indexOf(model::Param::Radius)];
    for (const double radius : {1e9, range.max + 0.5, range.min - 0.5}) {
        EXPECT_NE(r.wf->correctionRadiusProblem(radius).find("outside the brush's range"),
                  std::string::npos)
            << radius;
    }
    for (const double radius : {0.0, range.min, range.max}) {
        EXPECT_EQ(r.wf->correctionRadiusProblem(radius), "") << radius;
    }
}

TEST(WorkflowCorrect, APositiveOneSeedsAndLeavesTAndEps) {
    Rig r;
    r.load();
    ASSERT_TRUE(r.act(model::Correct{{8.0, 6.0, 4.0}, true, 2.0}).accepted);
    ASSERT_TRUE(r.act(model::Pause{}).accepted);
    const auto before = r.status().params;
    // i = 15 reads 1000, far above T + eps: a seed there all the same, T and eps as they were.
    ASSERT_TRUE(r.act(model::Correct{{15.0, 6.0, 4.0}, true, 1.0}).accepted);
    EXPECT_EQ(r.state(), State::Evolving);
    EXPECT_TRUE(r.engine.inside({15, 6, 4}));
    EXPECT_EQ(r.status().params.T, before.T);
    EXPECT_EQ(r.status().params.eps, before.eps);
    EXPECT_EQ(r.status().seeds, 2);
    EXPECT_EQ(r.status().insideExamples.size(), 2U) << "the first correction's probe and seed";
    EXPECT_EQ(r.status().paintedInside.size(), 1U) << "a correction is kept as a dab is";
    // It sticks: a keeping sphere, so the front cannot recede from tissue the threshold refuses.
    ASSERT_EQ(r.engine.barrierList().size(), 2U);
    EXPECT_TRUE(r.engine.barrierList()[1].keep);
    EXPECT_EQ(r.engine.barrierList()[1].sphere.centre, glm::vec3(15.0F, 6.0F, 4.0F));
    ASSERT_TRUE(r.act(model::Undo{}).accepted);
    EXPECT_EQ(r.engine.barriers(), 1);
}

// The level of the tissue under a later positive correction goes with its sphere, and its
// window reaches as far as the correction's run; the first correction's probe set T, erases
// admit nothing, and with runs everywhere there is no window.
TEST(WorkflowCorrect, ALaterPositiveOneCarriesItsTissuesLevel) {
    Rig r;
    r.load();
    ASSERT_TRUE(r.act(model::Correct{{8.0, 6.0, 4.0}, true, 2.0}).accepted);
    ASSERT_TRUE(r.act(model::Pause{}).accepted);
    ASSERT_TRUE(r.act(model::Correct{{15.0, 6.0, 4.0}, true, 1.5}).accepted);
    ASSERT_TRUE(r.act(model::Correct{{12.0, 6.0, 4.0}, false, 1.0}).accepted);
    const std::vector<model::Barrier>& b = r.engine.barrierList();
    ASSERT_EQ(b.size(), 3U);
    EXPECT_FALSE(b[0].tissue.has_value()) << "the first's level is T";
    ASSERT_TRUE(b[1].tissue.has_value());
    EXPECT_NEAR(b[1].tissue->level, 1000.0, 1e-3); // the fake reads 1000 at i = 15
    EXPECT_FLOAT_EQ(b[1].tissue->reach, 4.5F);     // 3 x the brush, as its run's reach
    EXPECT_FALSE(b[2].tissue.has_value());
    // The kiosk's tap in add mode while steering is the same correction.
    ASSERT_TRUE(r.act(model::AddSeed{{5.0, 6.0, 4.0}, 1.0}).accepted);
    ASSERT_TRUE(r.engine.barrierList().back().tissue.has_value());
    EXPECT_NEAR(r.engine.barrierList().back().tissue->level, -1000.0 + 2000.0 * 5.0 / 15.0, 1e-3);

    workflow::Settings everywhere = testSettings();
    everywhere.correctionReach = 0.0;
    Rig all(everywhere);
    all.load();
    ASSERT_TRUE(all.act(model::Correct{{8.0, 6.0, 4.0}, true, 2.0}).accepted);
    ASSERT_TRUE(all.act(model::Correct{{15.0, 6.0, 4.0}, true, 1.0}).accepted);
    ASSERT_EQ(all.engine.barrierList().size(), 2U);
    EXPECT_FALSE(all.engine.barrierList()[1].tissue.has_value());
}

TEST(WorkflowCorrect, ANegativeOneSticksAndUndoTakesTheBarrierBack) {
    Rig r;
    r.load();
    ASSERT_TRUE(r.act(model::Correct{{8.0, 6.0, 4.0}, true, 3.0}).accepted);
    ASSERT_TRUE(r.act(model::Pause{}).accepted);
    ASSERT_TRUE(r.act(model::Correct{{10.0, 6.0, 4.0}, false, 1.0}).accepted);
    EXPECT_EQ(r.state(), State::Evolving);
    EXPECT_FALSE(r.engine.inside({10, 6, 4}));
    ASSERT_EQ(r.engine.barrierList().size(), 2U); // the first correction's and this one
    EXPECT_EQ(r.engine.barrierList()[1].sphere.centre, glm::vec3(10.0F, 6.0F, 4.0F));
    EXPECT_FALSE(r.engine.barrierList()[1].keep);
    EXPECT_EQ(r.status().paintedOutside.size(), 1U);
    EXPECT_EQ(r.status().erasures, 1);
    ASSERT_TRUE(r.act(model::Undo{}).accepted);
    EXPECT_EQ(r.engine.barriers(), 1);
    EXPECT_TRUE(r.engine.inside({10, 6, 4}));
    ASSERT_TRUE(r.act(model::Redo{}).accepted);
    EXPECT_EQ(r.engine.barriers(), 2);
    ASSERT_TRUE(r.act(model::Restart{}).accepted);
    EXPECT_EQ(r.engine.barriers(), 0) << "a restart clears the no-go spheres with the surface";
}

// Every correction trains classify for as long as it stands: the newest six taps' rule would
// drop a session's first erases, and with them what they taught.
TEST(WorkflowCorrect, EveryCorrectionStaysAnExampleUntilUndone) {
    Rig r;
    r.load();
    ASSERT_TRUE(r.act(model::Correct{{8.0, 6.0, 4.0}, true, 2.0}).accepted);
    const std::size_t n = model::kMaxExamples + 3;
    for (std::size_t c = 0; c < n; ++c) {
        ASSERT_TRUE(r.act(model::Pause{}).accepted);
        const double i = 1.0 + static_cast<double>(c);
        ASSERT_TRUE(r.act(model::Correct{{i, 2.0, 4.0}, false, 0.5}).accepted) << c;
    }
    ASSERT_EQ(r.status().paintedOutside.size(), n);
    EXPECT_EQ(r.status().paintedOutside.front().centre, glm::vec3(1.0F, 2.0F, 4.0F));
    EXPECT_TRUE(r.status().outsideExamples.empty());
    ASSERT_TRUE(r.act(model::Undo{}).accepted);
    EXPECT_EQ(r.status().paintedOutside.size(), n - 1);
}

TEST(WorkflowCorrect, AnEditWhileSteeringSticksButNotBeforeTheRun) {
    Rig r;
    r.load();
    r.seed({8.0, 6.0, 4.0}, 3.0);
    ASSERT_TRUE(r.act(model::Erase{{9.0, 6.0, 4.0}, 1.0}).accepted);
    ASSERT_TRUE(r.act(model::AddSeed{{5.0, 6.0, 4.0}, 1.0}).accepted);
    EXPECT_EQ(r.engine.barriers(), 0) << "seeding: edits shape the start, nothing to hold";
    ASSERT_TRUE(r.act(model::Run{}).accepted);
    ASSERT_TRUE(r.act(model::Erase{{7.0, 6.0, 4.0}, 1.0}).accepted);
    ASSERT_TRUE(r.act(model::AddSeed{{12.0, 6.0, 4.0}, 1.0}).accepted);
    ASSERT_EQ(r.engine.barriers(), 2);
    EXPECT_FALSE(r.engine.barrierList()[0].keep);
    EXPECT_TRUE(r.engine.barrierList()[1].keep);
}

TEST(WorkflowCorrect, BeyondTheBarriersTheEraseStandsAndSaysSo) {
    Rig r;
    r.load();
    ASSERT_TRUE(r.act(model::Correct{{8.0, 6.0, 4.0}, true, 6.0}).accepted);
    for (std::size_t n = 0; n < model::kMaxBarriers; ++n) {
        ASSERT_TRUE(r.act(model::Correct{{8.0, 6.0, 4.0}, true, 6.0}).accepted);
        ASSERT_TRUE(
            r.act(model::Correct{{4.0 + 0.5 * static_cast<double>(n), 6.0, 4.0}, false, 0.5})
                .accepted);
    }
    EXPECT_EQ(r.engine.barriers(), static_cast<int>(model::kMaxBarriers));
    ASSERT_TRUE(r.act(model::Correct{{8.0, 6.0, 4.0}, false, 1.0}).accepted);
    EXPECT_FALSE(r.engine.inside({8, 6, 4}));
    EXPECT_NE(r.status().message.find("may grow back"), std::string::npos) << r.status().message;
}

// A later correction's run reaches only around it (Settings::correctionReach brush radii); the
// reach ends with the run, or with the operator's change of a parameter.
TEST(WorkflowCorrect, ALaterOneRunsWithinItsReachUntilTheRunEnds) {
    Rig r;
    r.load();
    ASSERT_TRUE(r.act(model::Correct{{8.0, 6.0, 4.0}, true, 2.0}).accepted);
    ASSERT_TRUE(r.act(model::Pause{}).accepted);
    ASSERT_TRUE(r.act(model::Correct{{10.0, 6.0, 4.0}, false, 1.5}).accepted);
    ASSERT_TRUE(r.engine.reach().has_value());
    EXPECT_EQ(r.engine.reach()->sphere.centre, glm::vec3(10.0F, 6.0F, 4.0F));
    EXPECT_FLOAT_EQ(r.engine.reach()->sphere.radius, 4.5F); // 3 x the brush
    for (int i = 0; i < 100 && r.state() == State::Evolving; ++i) {
        r.wf->evolve(10);
    }
    ASSERT_EQ(r.state(), State::Paused) << "converged";
    EXPECT_FALSE(r.engine.reach().has_value()) << "the next run is the whole surface's";

    ASSERT_TRUE(r.act(model::Correct{{12.0, 6.0, 4.0}, true, 1.0}).accepted);
    ASSERT_TRUE(r.engine.reach().has_value());
    ASSERT_TRUE(r.act(model::NudgeParam{model::Param::T, 1.0}).accepted);
    EXPECT_FALSE(r.engine.reach().has_value()) << "a new T applies everywhere";
    EXPECT_EQ(r.state(), State::Evolving);

    // With classify, each correction is an example: the speed changes everywhere, and so does
    // the run.
    workflow::Settings learning = testSettings();
    learning.defaultSpeed = model::SpeedKind::Classify;
    Rig classify(learning);
    classify.load();
    ASSERT_TRUE(classify.act(model::Correct{{8.0, 6.0, 4.0}, true, 2.0}).accepted);
    ASSERT_TRUE(classify.act(model::Pause{}).accepted);
    ASSERT_TRUE(classify.act(model::Correct{{12.0, 6.0, 4.0}, false, 1.0}).accepted);
    EXPECT_EQ(classify.status().speedInForce, model::SpeedKind::Classify);
    EXPECT_FALSE(classify.engine.reach().has_value());
    // An added part is missing where it was put: classify learns from it too, but its run
    // stays around it (the sarcoma CT's leak came back on a positive click's global run).
    const std::size_t trained = classify.engine.speeds.size();
    ASSERT_TRUE(classify.act(model::Correct{{10.0, 8.0, 4.0}, true, 1.0}).accepted);
    EXPECT_EQ(classify.engine.speeds.size(), trained + 1) << "it is an example";
    ASSERT_TRUE(classify.engine.reach().has_value());
    EXPECT_EQ(classify.engine.reach()->sphere.centre, glm::vec3(10.0F, 8.0F, 4.0F));
    EXPECT_FLOAT_EQ(classify.engine.reach()->sphere.radius, 3.0F);

    workflow::Settings everywhere = testSettings();
    everywhere.correctionReach = 0.0;
    Rig all(everywhere);
    all.load();
    ASSERT_TRUE(all.act(model::Correct{{8.0, 6.0, 4.0}, true, 2.0}).accepted);
    ASSERT_TRUE(all.act(model::Correct{{12.0, 6.0, 4.0}, true, 1.0}).accepted);
    EXPECT_FALSE(all.engine.reach().has_value());
}

// An erase that changed the speed runs over the whole surface, watched: grown by more than
// Settings::eraseRunGrowth of what the surface held before it, the run goes back to the erase
// and on from there, beyond the erase's reach only withdrawing.
TEST(WorkflowCorrect, AnEraseRunThatGrowsTooFarIsTakenBackToTheErase) {
    for (const double growth : {0.25, 0.0, 10.0}) {
        workflow::Settings learning = testSettings();
        learning.defaultSpeed = model::SpeedKind::Classify;
        learning.eraseRunGrowth = growth;
        Rig r(learning);
        r.load();
        ASSERT_TRUE(r.act(model::Correct{{8.0, 6.0, 4.0}, true, 2.0}).accepted);
        ASSERT_TRUE(r.act(model::Pause{}).accepted);
        const std::size_t held = r.engine.insideVoxels();
        ASSERT_TRUE(r.act(model::Correct{{10.0, 6.0, 4.0}, false, 1.0}).accepted);
        ASSERT_EQ(r.status().speedInForce, model::SpeedKind::Classify);
        ASSERT_FALSE(r.engine.reach().has_value()) << "its run is the whole surface's";
        const std::size_t erased = r.engine.insideVoxels();
        ASSERT_LT(erased, held);
        // A creep far from the erase, as big again as the surface.
        r.engine.stepGrows = model::Sphere{{3.0F, 6.0F, 4.0F}, 2.0F};
        r.wf->evolve(10);
        EXPECT_EQ(r.state(), State::Evolving);
        if (growth != 0.25) {
            EXPECT_TRUE(r.engine.inside({3, 6, 4})) << "no limit, or far above it";
            EXPECT_FALSE(r.engine.reach().has_value());
            continue;
        }
        EXPECT_FALSE(r.engine.inside({3, 6, 4})) << "taken back";
        EXPECT_EQ(r.engine.insideVoxels(), erased) << "to the surface the erase left";
        ASSERT_TRUE(r.engine.reach().has_value());
        EXPECT_TRUE(r.engine.reach()->recedeOutside);
        EXPECT_EQ(r.engine.reach()->sphere.centre, glm::vec3(10.0F, 6.0F, 4.0F));
        EXPECT_FLOAT_EQ(r.engine.reach()->sphere.radius, 3.0F); // 3 x the brush
        EXPECT_NE(r.status().message.find("back to the erase"), std::string::npos)
            << r.status().message;
        EXPECT_TRUE(r.status().canUndo) << "the erase is still one undo step";
        EXPECT_EQ(r.status().eraseRunsTakenBack, 1);
        EXPECT_TRUE(r.engine.withdrawLimit().has_value()) << "from the same surface";
        // Once: the run goes on from there, whatever it grows to (this fake ignores the reach).
        r.wf->evolve(10);
        EXPECT_TRUE(r.engine.inside({3, 6, 4}));
        EXPECT_TRUE(r.engine.reach()->recedeOutside);

        // The next erase under the same speed would creep as well: its run withdraws beyond its
        // reach from the start, until the operator changes T.
        r.engine.stepGrows.reset();
        ASSERT_TRUE(r.act(model::Pause{}).accepted);
        ASSERT_TRUE(r.act(model::Correct{{4.0, 6.0, 4.0}, false, 1.0}).accepted);
        ASSERT_TRUE(r.engine.reach().has_value());
        EXPECT_TRUE(r.engine.reach()->recedeOutside);
        EXPECT_EQ(r.engine.reach()->sphere.centre, glm::vec3(4.0F, 6.0F, 4.0F));
        EXPECT_EQ(r.status().erasesWithdrawOnly, 1);
        EXPECT_TRUE(r.engine.withdrawLimit().has_value());
        EXPECT_NE(r.status().message.find("only withdraws"), std::string::npos)
            << r.status().message;
        ASSERT_TRUE(r.act(model::NudgeParam{model::Param::T, 1.0}).accepted);
        ASSERT_TRUE(r.act(model::Pause{}).accepted);
        ASSERT_TRUE(r.act(model::Correct{{5.0, 6.0, 4.0}, false, 1.0}).accepted);
        EXPECT_FALSE(r.engine.reach().has_value()) << "a new T: watched again, run everywhere";
        EXPECT_EQ(r.status().erasesWithdrawOnly, 1);
    }
}

// Beyond its reach an erase's run takes the surface back at most Settings::eraseWithdrawMm
// (model::WithdrawLimit): the engine holds the limit for the run, from the surface the erase
// left, and lets it go when the run stops or the level set changes. A positive correction's run
// sets none.
TEST(WorkflowCorrect, AnErasesRunTakesTheSurfaceBackAtMostTheWithdrawDepthBeyondItsReach) {
    for (const double depth : {4.0, 0.0}) {
        workflow::Settings learning = testSettings();
        learning.defaultSpeed = model::SpeedKind::Classify;
        learning.eraseWithdrawMm = depth;
        Rig r(learning);
        r.load();
        ASSERT_TRUE(r.act(model::Correct{{8.0, 6.0, 4.0}, true, 2.0}).accepted);
        EXPECT_FALSE(r.engine.withdrawLimit().has_value()) << "the first run's";
        ASSERT_TRUE(r.act(model::Pause{}).accepted);
        ASSERT_TRUE(r.act(model::Correct{{10.0, 6.0, 4.0}, false, 1.0}).accepted);
        ASSERT_EQ(r.state(), State::Evolving);
        ASSERT_FALSE(r.engine.reach().has_value()) << "its run is the whole surface's";
        if (depth == 0.0) {
            EXPECT_FALSE(r.engine.withdrawLimit().has_value()) << "0: no limit";
            continue;
        }
        ASSERT_TRUE(r.engine.withdrawLimit().has_value());
        EXPECT_EQ(r.engine.withdrawLimit()->around.centre, glm::vec3(10.0F, 6.0F, 4.0F));
        EXPECT_FLOAT_EQ(r.engine.withdrawLimit()->around.radius, 3.0F); // the reach: 3 x brush
        EXPECT_DOUBLE_EQ(r.engine.withdrawLimit()->depthMm, 4.0);
        ASSERT_TRUE(r.act(model::Pause{}).accepted);
        EXPECT_FALSE(r.engine.withdrawLimit().has_value()) << "the run stopped";
        ASSERT_TRUE(r.act(model::Correct{{6.0, 6.0, 4.0}, true, 1.0}).accepted);
        EXPECT_FALSE(r.engine.withdrawLimit().has_value()) << "an added part's run";
        // Another change of the level set while the erase's run lasts: not the surface it kept.
        ASSERT_TRUE(r.act(model::Pause{}).accepted);
        ASSERT_TRUE(r.act(model::Correct{{11.0, 6.0, 4.0}, false, 1.0}).accepted);
        ASSERT_TRUE(r.engine.withdrawLimit().has_value());
        ASSERT_TRUE(r.act(model::Undo{}).accepted);
        EXPECT_FALSE(r.engine.withdrawLimit().has_value()) << "undone";
    }
}

TEST(WorkflowCorrect, ReviewAndDoneRefuseIt) {
    Rig r;
    r.driveTo(State::Review);
    EXPECT_FALSE(r.act(model::Correct{{8.0, 6.0, 4.0}, true, 1.0}).accepted);
    EXPECT_EQ(r.state(), State::Review);
}

} // namespace
} // namespace steerseg::test
