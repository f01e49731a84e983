// model::SetBox and ClearBox: the operator's box (docs/steering.md "The box"), on the in-memory
// engine: what the engine is told, what undo and redo bring back, what is refused.
#include "support/workflow_rig.hpp"
#include "workflow/box_tissue.hpp"

#include <cmath>
#include <gtest/gtest.h>
#include <limits>

namespace steerseg::test {
namespace {

using model::State;

const model::Box kBox{{4, 2, 1}, {11, 9, 6}}; // centre (7.5, 5.5, 3.5) on the fake's 16x12x8

// The fake's values rise along i, four of them in the box's inner part (i 6..9), equally
// common: the histogram's peak is the lowest (the first of equal peaks), -200 at i = 6, and
// the seed goes where the probe reads it nearest the centre.
TEST(WorkflowBox, TheFirstBoxProbesAndSeedsWhereItsTissueLiesInOneUndoStep) {
    Rig r;
    r.load();
    const float T0 = r.status().params.T;
    const std::optional<workflow::TissuePeak> tissue =
        workflow::dominantTissue(r.engine.values(workflow::innerBox(kBox), 1000));
    ASSERT_TRUE(tissue.has_value());
    EXPECT_NEAR(tissue->level, -200.0, 1e-9);
    ASSERT_TRUE(r.act(model::SetBox{kBox}).accepted);
    EXPECT_EQ(r.state(), State::Seeding) << "the operator runs it, as after a seed";
    ASSERT_TRUE(r.status().box.has_value());
    EXPECT_EQ(*r.status().box, kBox);
    ASSERT_FALSE(r.engine.speeds.empty());
    EXPECT_EQ(r.engine.speeds.back().box, kBox) << "the engine holds the surface in it";
    EXPECT_NEAR(r.status().params.T, -200.0, 1e-3);
    ASSERT_EQ(r.status().insideExamples.size(), 1U);
    const glm::vec3 at = r.status().insideExamples[0].centre;
    EXPECT_EQ(at.x, 6.0F) << "where the probe reads the tissue";
    EXPECT_TRUE(r.engine.inside(glm::ivec3(glm::round(at))));
    EXPECT_EQ(r.status().seeds, 1);
    ASSERT_TRUE(r.act(model::Undo{}).accepted);
    EXPECT_FALSE(r.status().hasLevelSet);
    EXPECT_FALSE(r.status().box.has_value());
    EXPECT_FALSE(r.engine.speeds.back().box.has_value());
    EXPECT_EQ(r.status().params.T, T0);
    ASSERT_TRUE(r.act(model::Redo{}).accepted);
    EXPECT_EQ(r.status().box, kBox);
    EXPECT_TRUE(r.engine.inside(glm::ivec3(glm::round(at))));
}

// The box's tissue: the histogram's highest peak, its level and spread, whatever else the box
// holds beside it (fat, air, a brighter neighbour).
TEST(BoxTissue, ThePeakOfAMixtureIsTheTissueThatFillsMost) {
    std::vector<double> values;
    // 60 % tissue around 50 (sd 10), 30 % fat around -100 (sd 15), 10 % bone at 700: the
    // quantiles of logistic distributions of those spreads, a deterministic stand-in for noise.
    const auto normal = [&values](double mean, double sd, int n) {
        for (int i = 0; i < n; ++i) {
            const double u = (i + 0.5) / n;
            values.push_back(mean + sd * std::log(u / (1.0 - u)) * std::sqrt(3.0) / 3.14159265);
        }
    };
    normal(50.0, 10.0, 6000);
    normal(-100.0, 15.0, 3000);
    normal(700.0, 30.0, 1000);
    values.push_back(std::numeric_limits<double>::quiet_NaN());
    const std::optional<workflow::TissuePeak> p = workflow::dominantTissue(values);
    ASSERT_TRUE(p.has_value());
    EXPECT_NEAR(p->level, 50.0, 6.0);
    EXPECT_GT(p->sigma, 5.0);
    EXPECT_LT(p->sigma, 25.0) << "one bin is 13 units wide here";
    // A few values are their own mean and spread; none is nothing.
    const std::optional<workflow::TissuePeak> few = workflow::dominantTissue({1.0, 3.0});
    ASSERT_TRUE(few.has_value());
    EXPECT_DOUBLE_EQ(few->level, 2.0);
    EXPECT_DOUBLE_EQ(few->sigma, 1.0);
    EXPECT_FALSE(workflow::dominantTissue({std::numeric_limits<double>::infinity()}).has_value());
    EXPECT_EQ(workflow::innerBox(kBox), (model::Box{{6, 4, 2}, {9, 7, 5}}));
}

TEST(WorkflowBox, ALaterBoxMovesItAndTheSurfaceStays) {
    Rig r;
    r.driveTo(State::Paused);
    const int seeds = r.status().seeds;
    const model::Box moved{{2, 2, 0}, {13, 11, 7}};
    ASSERT_TRUE(r.act(model::SetBox{kBox}).accepted);
    ASSERT_TRUE(r.act(model::SetBox{moved}).accepted);
    EXPECT_EQ(r.state(), State::Paused);
    EXPECT_EQ(r.status().seeds, seeds) << "no seed of its own on a surface";
    EXPECT_EQ(r.engine.speeds.back().box, moved);
    ASSERT_TRUE(r.act(model::Undo{}).accepted);
    EXPECT_EQ(r.status().box, kBox);
    ASSERT_TRUE(r.act(model::ClearBox{}).accepted);
    EXPECT_FALSE(r.engine.speeds.back().box.has_value());
    const auto again = r.act(model::ClearBox{});
    EXPECT_FALSE(again.accepted);
    EXPECT_EQ(again.reason, "no box to clear");
}

TEST(WorkflowBox, AnInvertedOrOutsideBoxIsRefusedWithWhy) {
    Rig r;
    r.load();
    const auto inverted = r.act(model::SetBox{{{9, 2, 1}, {4, 9, 6}}});
    EXPECT_FALSE(inverted.accepted);
    EXPECT_NE(inverted.reason.find("inverted on i"), std::string::npos) << inverted.reason;
    const auto outside = r.act(model::SetBox{{{4, 2, 1}, {11, 9, 8}}});
    EXPECT_FALSE(outside.accepted);
    EXPECT_NE(outside.reason.find("outside the scan"), std::string::npos) << outside.reason;
    const auto negative = r.act(model::SetBox{{{-1, 2, 1}, {11, 9, 6}}});
    EXPECT_FALSE(negative.accepted);
    EXPECT_EQ(r.state(), State::Inspect);
    EXPECT_FALSE(r.status().hasLevelSet);
    EXPECT_FALSE(r.status().box.has_value());
}

TEST(WorkflowBox, ASeedBeyondTheBoxMovesTheBoxToHoldIt) {
    Rig r;
    r.load();
    ASSERT_TRUE(r.act(model::SetBox{kBox}).accepted);
    ASSERT_TRUE(r.act(model::Run{}).accepted);
    ASSERT_TRUE(r.act(model::Correct{{13.0, 5.0, 3.0}, true, 1.0}).accepted);
    ASSERT_TRUE(r.status().box.has_value());
    EXPECT_EQ(r.status().box->hi.x, 14) << "the sphere's reach along i: 13 + 1";
    EXPECT_EQ(r.status().box->lo, kBox.lo);
    EXPECT_EQ(r.engine.speeds.back().box, r.status().box);
    // An erase beyond it leaves it be.
    const model::Box before = *r.status().box;
    ASSERT_TRUE(r.act(model::Correct{{1.0, 1.0, 0.0}, false, 1.0}).accepted);
    EXPECT_EQ(r.status().box, before);
}

// The box's tissue teaches classify its inside at every place it was read; the outside still
// waits for the operator's word (a negative correction, an outside mark), as after a click.
TEST(WorkflowBox, ClassifyLearnsTheInsideFromTheBoxAndWaitsForAnOutside) {
    Rig r;
    r.load();
    ASSERT_TRUE(r.act(model::SetSpeed{model::SpeedKind::Classify}).accepted);
    ASSERT_TRUE(r.act(model::SetBox{kBox}).accepted);
    EXPECT_EQ(r.status().speedInForce, model::SpeedKind::Threshold) << "no outside example yet";
    // The fake reads the tissue (-200) wherever i = 6: the probe's and the grid's places there.
    ASSERT_FALSE(r.status().paintedInside.empty());
    for (const model::Sphere& s : r.status().paintedInside) {
        EXPECT_EQ(s.centre.x, 6.0F);
        EXPECT_TRUE(model::contains(kBox, glm::ivec3(glm::round(s.centre))));
    }
    ASSERT_TRUE(r.act(model::MarkOutside{{1.0, 1.0, 1.0}, 0.0}).accepted);
    EXPECT_EQ(r.status().speedInForce, model::SpeedKind::Classify);
    EXPECT_EQ(r.engine.speeds.back().box, kBox);
}

TEST(WorkflowBox, ReviewAndDoneRefuseIt) {
    Rig r;
    r.driveTo(State::Review);
    const auto out = r.act(model::SetBox{kBox});
    EXPECT_FALSE(out.accepted);
    EXPECT_EQ(out.reason, "go back to steering to edit the surface");
}

} // namespace
} // namespace steerseg::test
