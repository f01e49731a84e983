// Session::setSpeed: validation, classify's refusal, the timings, and a speed change restarting
// the convergence clock as a parameter change does.
#include "io/scan_reader.hpp"
#include "session/session.hpp"
#include "support/gpu_fixture.hpp"

#include <cmath>
#include <gtest/gtest.h>
#include <stdexcept>

namespace steerseg::test {
namespace {

class SessionSpeedTest : public GpuTest {};

const solver::Sphere kLesionSeed{{80.0F, 56.0F, 52.0F}, 5.0F};

TEST_F(SessionSpeedTest, RefusesBadSettingsAndKeepsTheLastGoodSpeed) {
    session::Session s = session::Session::open(io::kBuiltinSample);
    session::SpeedSettings edge;
    edge.kind = speed::SpeedKind::Edge;
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
    EXPECT_EQ(s.speed().kind, speed::SpeedKind::Edge);
    EXPECT_GT(s.speedTiming().preprocessingSeconds, 0.0);
    EXPECT_EQ(s.speedTiming().trainingSeconds, 0.0);

    session::SpeedSettings classify;
    classify.kind = speed::SpeedKind::Classify;
    classify.inside = {kLesionSeed};
    EXPECT_THROW(s.setSpeed(classify), std::invalid_argument); // no outside example
    classify.outside = {{{20.0F, 20.0F, 20.0F}, 4.0F}};
    classify.inside.push_back({{500.0F, 0.0F, 0.0F}, 2.0F}); // outside the scan
    EXPECT_THROW(s.setSpeed(classify), std::invalid_argument);
    classify.inside.pop_back();
    EXPECT_THROW(s.setSpeed(classify), std::runtime_error); // not built yet
    EXPECT_EQ(s.speed().kind, speed::SpeedKind::Edge);
}

TEST_F(SessionSpeedTest, ASpeedChangeRestartsTheConvergenceClock) {
    session::Session s = session::Session::open(io::kBuiltinSample);
    s.addSeed(kLesionSeed);
    s.setParams({800.0F, 100.0F, 0.8F});
    const session::RunOutcome first = s.run({session::RunMode::Converge, 3000, 0.0F});
    ASSERT_TRUE(first.result.converged);
    const std::vector<std::uint8_t> threshold = s.mask();
    session::SpeedSettings edge;
    edge.kind = speed::SpeedKind::Edge;
    edge.kappa = 1e6F; // g = 1 to float precision: the same speed, but a change
    s.setSpeed(edge);
    EXPECT_FALSE(s.converged());
    const session::RunOutcome second = s.run({session::RunMode::Converge, 3000, 0.0F});
    EXPECT_TRUE(second.result.converged);
    EXPECT_GE(second.result.iterations, 20); // the clock restarted
    EXPECT_EQ(s.mask(), threshold);
}

} // namespace
} // namespace steerseg::test
