// Session::setSpeed: validation, the timings, a speed change restarting the convergence clock as
// a parameter change does, and the classification speed's front stopping at a texture border.
#include "scan/scan_reader.hpp"
#include "session/session.hpp"
#include "support/gpu_fixture.hpp"
#include "support/two_textures.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <gtest/gtest.h>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

namespace steerseg::test {
namespace {

class SessionSpeedTest : public GpuTest {};

const model::Sphere kLesionSeed{{80.0F, 56.0F, 52.0F}, 5.0F};

TEST_F(SessionSpeedTest, RefusesBadSettingsAndKeepsTheLastGoodSpeed) {
    session::Session s = session::Session::open(scan::kBuiltinSample);
    session::SpeedSettings edge;
    edge.kind = model::SpeedKind::Edge;
    EXPECT_THROW(s.setSpeed(edge), std::invalid_argument); // no kappa
    edge.kappa = NAN;
    EXPECT_THROW(s.setSpeed(edge), std::invalid_argument);
    edge.kappa = 15.0F;
    edge.smoothing = {3, 0.0F}; // smoothing without a conductance
    EXPECT_THROW(s.setSpeed(edge), std::invalid_argument);
    edge.smoothing = {3, 45.0F};
    int smoothingSteps = 0;
    s.setSpeed(edge, [&](std::string_view stage, int done, int total) {
        if (stage == "smoothing") {
            ++smoothingSteps;
            EXPECT_EQ(done, smoothingSteps);
            EXPECT_EQ(total, 3);
        }
    });
    EXPECT_EQ(smoothingSteps, 3);
    EXPECT_EQ(s.speed().kind, model::SpeedKind::Edge);
    EXPECT_GT(s.speedTiming().preprocessingSeconds, 0.0);
    EXPECT_EQ(s.speedTiming().trainingSeconds, 0.0);

    session::SpeedSettings classify;
    classify.kind = model::SpeedKind::Classify;
    classify.inside = {kLesionSeed};
    EXPECT_THROW(s.setSpeed(classify), std::invalid_argument); // no outside example
    classify.outside = {{{20.0F, 20.0F, 20.0F}, 4.0F}};
    classify.inside.push_back({{500.0F, 0.0F, 0.0F}, 2.0F}); // outside the scan
    EXPECT_THROW(s.setSpeed(classify), std::invalid_argument);
    EXPECT_EQ(s.speed().kind, model::SpeedKind::Edge);
}

TEST_F(SessionSpeedTest, ASpeedChangeRestartsTheConvergenceClock) {
    session::Session s = session::Session::open(scan::kBuiltinSample);
    s.addSeed(kLesionSeed);
    s.setParams({800.0F, 100.0F, 0.8F});
    const session::RunOutcome first = s.run({session::RunMode::Converge, 3000, 0.0F});
    ASSERT_TRUE(first.result.converged);
    const std::vector<std::uint8_t> threshold = s.mask();
    session::SpeedSettings edge;
    edge.kind = model::SpeedKind::Edge;
    edge.kappa = 1e6F; // g = 1 to float precision: the same speed, but a change
    s.setSpeed(edge);
    EXPECT_FALSE(s.converged());
    const session::RunOutcome second = s.run({session::RunMode::Converge, 3000, 0.0F});
    EXPECT_TRUE(second.result.converged);
    // The clock restarted: the run went on to a pool check at least (the front does not move,
    // so its bricks fall asleep and the first check may already call it converged).
    EXPECT_GE(second.result.iterations, s.options().checkInterval);
    // The same speed leaves the surface where it was, up to the voxels of the phantom's partial
    // volume whose intensity sits at T - eps, where the data term is about 0 and a converged
    // front still creeps.
    const std::vector<std::uint8_t> after = s.mask();
    ASSERT_EQ(after.size(), threshold.size());
    std::size_t changed = 0;
    std::size_t inside = 0;
    for (std::size_t n = 0; n < after.size(); ++n) {
        changed += after[n] != threshold[n] ? 1 : 0;
        inside += threshold[n];
    }
    ASSERT_GT(inside, 1000U);
    EXPECT_LE(changed, inside / 100) << changed << " of " << inside << " voxels changed side";
}

// Two textures of one mean intensity (100 +- 8 below x = 24, 100 +- 40 from there): no threshold
// separates them, the classifier's neighbourhood statistics do.
constexpr glm::ivec3 kTwoDims{48, 32, 32};
constexpr int kBorderX = 24;

Volume twoTextures() {
    Geometry g;
    g.dims = kTwoDims;
    Volume v(VoxelType::Float32, g);
    const std::vector<float> values = twoTextureIntensities(kTwoDims, kBorderX, 12345U);
    std::copy(values.begin(), values.end(), v.voxels<float>().begin());
    v.invalidateStats();
    return v;
}

TEST_F(SessionSpeedTest, TheClassifiedFrontStopsAtTheTextureBorder) {
    session::Session s(twoTextures(), "test");
    session::SpeedSettings classify;
    classify.kind = model::SpeedKind::Classify;
    classify.inside = {{{10.0F, 16.0F, 16.0F}, 6.0F}};
    classify.outside = {{{37.0F, 16.0F, 16.0F}, 6.0F}};
    std::vector<std::string> stages;
    s.setSpeed(classify, [&](std::string_view stage, int, int) { stages.emplace_back(stage); });
    EXPECT_EQ(stages, (std::vector<std::string>{"training", "training"}));
    EXPECT_GT(s.speedTiming().trainingSeconds, 0.0);
    s.setParams({100.0F, 30.0F, 0.7F}); // T and eps do not enter the classification speed
    s.addSeed({{10.0F, 16.0F, 16.0F}, 3.0F});
    const session::RunOutcome r = s.run({session::RunMode::Converge, 3000, 0.0F});
    EXPECT_TRUE(r.result.converged);
    const std::vector<std::uint8_t> mask = s.mask();
    std::size_t calm = 0;
    std::size_t beyond = 0; // inside, two voxels or more past the border
    std::size_t n = 0;
    for (int k = 0; k < kTwoDims.z; ++k) {
        for (int j = 0; j < kTwoDims.y; ++j) {
            for (int i = 0; i < kTwoDims.x; ++i) {
                const bool in = mask[n++] != 0;
                calm += in && i < kBorderX ? 1 : 0;
                beyond += in && i >= kBorderX + 2 ? 1 : 0;
            }
        }
    }
    const double calmVoxels = kBorderX * kTwoDims.y * kTwoDims.z;
    EXPECT_GT(static_cast<double>(calm) / calmVoxels, 0.9);
    EXPECT_LT(static_cast<double>(beyond) / calmVoxels, 0.02);
}

// A box that moves alone keeps the trained classifier and the speed it evaluated where the front
// went (each knob detent on a box's face retrained it); any other change retrains.
TEST_F(SessionSpeedTest, ABoxAloneMovesTheBoxAndKeepsTheClassifier) {
    session::Session s(twoTextures(), "test");
    session::SpeedSettings classify;
    classify.kind = model::SpeedKind::Classify;
    classify.inside = {{{10.0F, 16.0F, 16.0F}, 6.0F}};
    classify.outside = {{{37.0F, 16.0F, 16.0F}, 6.0F}};
    s.setSpeed(classify);
    s.setParams({100.0F, 30.0F, 0.7F});
    s.addSeed({{10.0F, 16.0F, 16.0F}, 3.0F});
    s.run({session::RunMode::Iterations, 40, 0.0F});
    const std::uint32_t evaluated = s.speedBricksEvaluated();
    ASSERT_GT(evaluated, 0U);
    classify.box = model::Box{{2, 2, 2}, {20, 29, 29}};
    int stages = 0;
    s.setSpeed(classify, [&](std::string_view, int, int) { ++stages; });
    EXPECT_EQ(stages, 0) << "no training for a box";
    EXPECT_EQ(s.speedBricksEvaluated(), evaluated);
    EXPECT_EQ(s.speed().box, classify.box);
    classify.outside.push_back({{30.0F, 16.0F, 16.0F}, 3.0F});
    s.setSpeed(classify, [&](std::string_view, int, int) { ++stages; });
    EXPECT_GT(stages, 0) << "a new example trains";
}

// The slice views' speed view shows the data term the solver runs, not the threshold speed of
// the parameters: on the two textures, the threshold (T 100, eps 60) is positive on both sides,
// the classifier's P(inside) - P(outside) only on the calm one.
TEST_F(SessionSpeedTest, TheSpeedViewShowsTheSpeedInForce) {
    session::Session s(twoTextures(), "test");
    s.setParams({100.0F, 60.0F, 0.7F});
    render::ViewParams view;
    view.kind = render::ViewKind::Axial;
    view.size = {96, 64};
    view.content = render::SliceContent::Speed;
    view.speed = {100.0, 60.0};
    view.contour = false;
    view.labels = false;
    // Fractions of green (the front grows) pixels left and right of the border, 3 voxels clear.
    const auto greenSides = [&]() {
        const std::optional<render::SliceFrame> frame = s.render(view);
        const RgbaImage picture = s.picture();
        int green[2] = {0, 0};
        int count[2] = {0, 0};
        for (int y = 0; y < picture.height; ++y) {
            for (int x = 0; x < picture.width; ++x) {
                const double i = (frame->origin + static_cast<double>(x) * frame->stepRight +
                                  static_cast<double>(y) * frame->stepDown)
                                     .x;
                if (std::abs(i - kBorderX) < 3.0 || i < 0.0 || i > kTwoDims.x - 1) {
                    continue;
                }
                const std::uint8_t* px = picture.at(x, y);
                const int side = i < kBorderX ? 0 : 1;
                green[side] += px[1] > px[2] ? 1 : 0;
                ++count[side];
            }
        }
        EXPECT_GT(count[0], 200);
        EXPECT_GT(count[1], 200);
        return std::array<double, 2>{static_cast<double>(green[0]) / count[0],
                                     static_cast<double>(green[1]) / count[1]};
    };
    const std::array<double, 2> threshold = greenSides();
    EXPECT_GT(threshold[0], 0.99);
    EXPECT_GT(threshold[1], 0.99);

    session::SpeedSettings classify;
    classify.kind = model::SpeedKind::Classify;
    classify.inside = {{{10.0F, 16.0F, 16.0F}, 6.0F}};
    classify.outside = {{{37.0F, 16.0F, 16.0F}, 6.0F}};
    s.setSpeed(classify);
    // Evaluated where the front goes (no front here), and for the view the rest of the scan.
    EXPECT_GT(s.evaluateSpeedAhead(1), 0U);
    s.completeSpeed();
    EXPECT_EQ(s.evaluateSpeedAhead(1), 0U);
    const std::array<double, 2> classified = greenSides();
    EXPECT_GT(classified[0], 0.9);
    EXPECT_LT(classified[1], 0.1);
}

} // namespace
} // namespace steerseg::test
