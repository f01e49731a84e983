// Painted strokes (model::PaintStroke): the brush along a path in add, erase or outside mode, one
// undo step, gap-free however far apart the points are, every dab training classify, and the
// refusals of paths that are not strokes.
#include "support/workflow_rig.hpp"
#include "workflow/audit_log.hpp"
#include "workflow/stroke_dabs.hpp"

#include <cmath>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>
#include <vector>

namespace steerseg::test {
namespace {

using model::PaintStroke;
using model::State;
using model::StrokeMode;

// The fake scan is 16 x 12 x 8: a line along i through its middle row.
PaintStroke line(StrokeMode mode, double radius = 1.0) {
    return PaintStroke{mode, {{1.0, 6.0, 4.0}, {14.0, 6.0, 4.0}}, radius};
}

bool paintedAlong(const FakeEngine& e, int from, int to) {
    for (int i = from; i <= to; ++i) {
        if (!e.inside({i, 6, 4})) {
            return false;
        }
    }
    return true;
}

TEST(WorkflowStroke, StrokeDabsLeaveNoGap) {
    const std::vector<glm::dvec3> points{{0, 0, 0}, {10, 0, 0}, {10, 7, 0}, {10, 7.2, 0}};
    const auto dabs = workflow::strokeDabs(points, 1.5, 100);
    ASSERT_TRUE(dabs.has_value());
    EXPECT_EQ(dabs->front(), points[0]);
    EXPECT_EQ((*dabs)[7], points[1]) << "10 voxels in ceil(10 / 1.5) = 7 equal steps";
    EXPECT_EQ(dabs->back(), points[2]) << "a point within the spacing adds nothing";
    for (std::size_t d = 1; d < dabs->size(); ++d) {
        EXPECT_LE(glm::length((*dabs)[d] - (*dabs)[d - 1]), 1.5 + 1e-12) << d;
    }
    EXPECT_EQ(workflow::strokeDabs(points, 1.5, 12), std::nullopt) << "13 dabs needed";
    EXPECT_EQ(workflow::strokeDabs(std::vector<glm::dvec3>{{1, 2, 3}}, 1.0, 1)->size(), 1U);
    // Through slices 3 pixels thick, 4 slices are 12 pixels: 8 steps of 1.5, not 3.
    const std::vector<glm::dvec3> through{{0, 0, 0}, {0, 0, 4}};
    EXPECT_EQ(workflow::strokeDabs(through, 1.5, 100, {1, 1, 3})->size(), 9U);
    EXPECT_EQ(workflow::strokeDabs(through, 1.5, 100)->size(), 4U);
}

TEST(WorkflowStroke, AnAddStrokeSeedsAlongItsPathAsOneUndoStep) {
    Rig rig;
    rig.load();
    const std::size_t depth = rig.wf->undoDepth();
    // Two points 13 voxels apart, as a fast drag sends them: the whole line is painted.
    ASSERT_TRUE(rig.act(line(StrokeMode::Add)).accepted);
    EXPECT_EQ(rig.state(), State::Seeding) << "like the first seed";
    EXPECT_TRUE(paintedAlong(rig.engine, 1, 14));
    EXPECT_FALSE(rig.engine.inside({8, 9, 4})) << "a radius-1 brush";
    EXPECT_EQ(rig.status().seeds, 1);
    EXPECT_EQ(rig.wf->undoDepth(), depth + 1);
    // Every dab is an inside example (more than the newest kMaxExamples taps keep).
    EXPECT_GT(rig.status().paintedInside.size(), model::kMaxExamples);
    EXPECT_EQ(rig.status().paintedInside.front().centre, glm::vec3(1.0F, 6.0F, 4.0F));
    EXPECT_EQ(rig.status().paintedInside.back().centre, glm::vec3(14.0F, 6.0F, 4.0F));

    ASSERT_TRUE(rig.act(model::Undo{}).accepted);
    EXPECT_EQ(rig.engine.insideVoxels(), 0U) << "one undo takes the whole stroke back";
    EXPECT_TRUE(rig.status().paintedInside.empty());
    EXPECT_EQ(rig.status().seeds, 0);
    ASSERT_TRUE(rig.act(model::Redo{}).accepted);
    EXPECT_TRUE(paintedAlong(rig.engine, 1, 14));
    EXPECT_FALSE(rig.status().paintedInside.empty());
    EXPECT_EQ(rig.engine.misuse(), 0) << rig.engine.lastMisuse();
}

TEST(WorkflowStroke, AnEraseStrokeCutsAlongItsPath) {
    Rig rig;
    rig.driveTo(State::Paused);
    ASSERT_TRUE(rig.act(model::AddSeed{{8.0, 6.0, 4.0}, 5.0}).accepted);
    const std::size_t before = rig.engine.insideVoxels();
    ASSERT_TRUE(rig.act(line(StrokeMode::Erase)).accepted);
    for (int i = 3; i <= 13; ++i) {
        EXPECT_FALSE(rig.engine.inside({i, 6, 4})) << i;
    }
    EXPECT_TRUE(rig.engine.inside({8, 9, 4})) << "beside the brush";
    EXPECT_EQ(rig.status().erasures, 1);
    EXPECT_TRUE(rig.status().paintedOutside.empty()) << "erasing teaches nothing";
    ASSERT_TRUE(rig.act(model::Undo{}).accepted);
    EXPECT_EQ(rig.engine.insideVoxels(), before);
}

TEST(WorkflowStroke, AnEraseStrokeThatEmptiesTheLevelSetPausesTheRun) {
    Rig rig;
    rig.driveTo(State::Evolving);
    ASSERT_TRUE(rig.act(line(StrokeMode::Erase, 6.0)).accepted);
    EXPECT_FALSE(rig.status().hasLevelSet);
    EXPECT_EQ(rig.state(), State::Paused);
}

TEST(WorkflowStroke, ClassifyLearnsFromEveryPaintedDab) {
    Rig rig;
    rig.load();
    ASSERT_TRUE(rig.act(model::SetSpeed{model::SpeedKind::Classify}).accepted);
    // Outside along the top row, inside along the middle: strokes alone, no tap.
    ASSERT_TRUE(rig.act(PaintStroke{StrokeMode::Outside, {{0.0, 0.0, 4.0}, {15.0, 0.0, 4.0}}, 1.0})
                    .accepted);
    EXPECT_EQ(rig.state(), State::Inspect) << "outside examples place no seed";
    EXPECT_EQ(rig.status().speedInForce, model::SpeedKind::Threshold) << "no inside example yet";
    ASSERT_TRUE(rig.act(line(StrokeMode::Add)).accepted);
    EXPECT_EQ(rig.status().speedInForce, model::SpeedKind::Classify);
    const workflow::SpeedChoice& sent = rig.engine.speeds.back();
    EXPECT_EQ(sent.kind, model::SpeedKind::Classify);
    EXPECT_EQ(sent.paintedInside.size(), rig.status().paintedInside.size());
    EXPECT_EQ(sent.paintedOutside.size(), rig.status().paintedOutside.size());
    EXPECT_GT(sent.paintedOutside.size(), model::kMaxExamples);
    // One undo takes the stroke's examples back with it: classify waits again.
    ASSERT_TRUE(rig.act(model::Undo{}).accepted);
    EXPECT_EQ(rig.status().speedInForce, model::SpeedKind::Threshold);
    // Clearing the examples clears the painted ones too.
    ASSERT_TRUE(rig.act(model::ClearExamples{}).accepted);
    EXPECT_TRUE(rig.status().paintedOutside.empty());
    EXPECT_EQ(rig.engine.misuse(), 0) << rig.engine.lastMisuse();
}

TEST(WorkflowStroke, RefusesWhatIsNotAStroke) {
    Rig rig;
    rig.driveTo(State::Seeding);
    const std::size_t depth = rig.wf->undoDepth();
    const auto refused = [&](const PaintStroke& s) { return rig.act(s).reason; };
    EXPECT_EQ(refused({StrokeMode::Add, {}, 1.0}), "a stroke needs at least one point");
    EXPECT_EQ(refused({StrokeMode::Add, {{1.0, 1.0, 1.0}, {std::nan(""), 1.0, 1.0}}, 1.0}),
              "stroke point 2 is not a finite position");
    EXPECT_EQ(refused({StrokeMode::Add, {{1.0, 1.0, 1.0}}, HUGE_VAL}),
              "a stroke needs a finite radius");
    EXPECT_EQ(refused({StrokeMode::Outside, {{1.0, 1.0, 1.0}, {16.0, 1.0, 1.0}}, 1.0}),
              "stroke point 2 (16, 1, 1) lies outside the scan (16 x 12 x 8 voxels)");
    PaintStroke many{StrokeMode::Add, {}, 1.0};
    many.points.assign(model::kMaxStrokePoints + 1, glm::dvec3(2.0));
    EXPECT_EQ(refused(many), "a stroke of 4097 points: at most 4096 in one stroke");
    // Corner to corner and back, thousands of times: more spheres than a stroke may take.
    PaintStroke scribble{StrokeMode::Add, {}, 1.0};
    for (std::size_t p = 0; p < model::kMaxStrokePoints; ++p) {
        scribble.points.push_back(p % 2 == 0 ? glm::dvec3(0.0) : glm::dvec3(15.0, 11.0, 7.0));
    }
    EXPECT_NE(refused(scribble).find("the stroke is too long for a brush of radius 1"),
              std::string::npos);
    EXPECT_EQ(rig.wf->undoDepth(), depth) << "nothing refused was recorded";
    // Review refuses it as it refuses a seed; an erase with nothing to erase is refused.
    Rig review;
    review.driveTo(State::Review);
    EXPECT_EQ(review.act(line(StrokeMode::Add)).reason, "go back to steering to edit the surface");
    Rig empty;
    empty.driveTo(State::Seeding);
    ASSERT_TRUE(empty.act(model::Restart{}).accepted);
    EXPECT_EQ(empty.act(line(StrokeMode::Erase)).reason, "nothing to erase");
}

TEST(WorkflowStroke, AStrokeThatFailsPartWayLeavesNothing) {
    Rig rig;
    rig.driveTo(State::Paused);
    const std::size_t inside = rig.engine.insideVoxels();
    const std::size_t depth = rig.wf->undoDepth();
    const std::size_t snapshots = rig.engine.liveSnapshots();
    rig.engine.editError = "GPU lost";
    EXPECT_EQ(rig.act(line(StrokeMode::Add)).reason, "GPU lost");
    rig.engine.editError.clear();
    EXPECT_EQ(rig.engine.insideVoxels(), inside);
    EXPECT_EQ(rig.wf->undoDepth(), depth);
    EXPECT_EQ(rig.engine.liveSnapshots(), snapshots);
    EXPECT_TRUE(rig.status().paintedInside.empty());
}

TEST(WorkflowStroke, TheAuditLogHoldsTheStrokeWithABoundedPath) {
    PaintStroke s{StrokeMode::Outside, {}, 2.5};
    for (int p = 0; p < 1000; ++p) {
        s.points.emplace_back(static_cast<double>(p), 1.0, 2.0);
    }
    const nlohmann::json v = workflow::actionValues(s);
    EXPECT_EQ(v["mode"], "outside");
    EXPECT_EQ(v["radius"], 2.5);
    EXPECT_EQ(v["point_count"], 1000);
    ASSERT_EQ(v["points"].size(), 256U);
    EXPECT_EQ(v["points"].front(), nlohmann::json::array({0.0, 1.0, 2.0}));
    EXPECT_EQ(v["points"].back(), nlohmann::json::array({999.0, 1.0, 2.0}));
    const nlohmann::json one = workflow::actionValues(PaintStroke{StrokeMode::Add, {{1, 2, 3}}, 0});
    EXPECT_EQ(one["points"], nlohmann::json::array({nlohmann::json::array({1.0, 2.0, 3.0})}));
}

} // namespace
} // namespace steerseg::test
