// The solver's own stop on the GPU: the settle rule wired into convergence (its window in
// iterations, restarted by an edit, no stop for a moving front), and the runaway watch stopping a
// fill that spills from a ball into a region of its intensity along a wide contact.
#include "solver/level_set_solver.hpp"
#include "support/gpu_fixture.hpp"
#include "support/solver_test_support.hpp"

#include <gtest/gtest.h>

namespace steerseg::test {
using namespace steerseg::solver; // the solver under test
using namespace steerseg::model;
namespace {

class SolverStopTest : public GpuTest {};

constexpr glm::ivec3 kDims{64, 32, 32};
constexpr glm::vec3 kBall{12.0F, 16.0F, 16.0F};
constexpr float kBallRadius = 9.0F;
constexpr int kSlabStart = 18; // x from which the whole cross-section has the ball's intensity
const LevelSetParams kParams{100.0F, 40.0F, 0.8F};

// A ball that touches a slab of its intensity along a disc of radius 6.7 (a tumour along a
// muscle of the same signal).
std::vector<float> ballBesideSlab() {
    std::vector<float> v = ballVolume(kDims, 0.0F, 100.0F, kBall, kBallRadius);
    for (int k = 0; k < kDims.z; ++k) {
        for (int j = 0; j < kDims.y; ++j) {
            for (int i = kSlabStart; i < kDims.x; ++i) {
                v[voxelIndex(kDims, i, j, k)] = 100.0F;
            }
        }
    }
    return v;
}

std::size_t insideSlab(const std::vector<std::uint8_t>& mask) {
    std::size_t n = 0;
    for (int k = 0; k < kDims.z; ++k) {
        for (int j = 0; j < kDims.y; ++j) {
            for (int i = kSlabStart; i < kDims.x; ++i) {
                n += mask[voxelIndex(kDims, i, j, k)];
            }
        }
    }
    return n;
}

TEST_F(SolverStopTest, TheSettleWindowCountsIterationsAndRestartsOnAnEdit) {
    // A ball of radius 8 shrinking under curvature alone (r^2 = r0^2 - 4t, dt = 1/8): it moves
    // for ~128 iterations. With a tolerance no front can exceed it settles as soon as a window
    // (64 iterations here) is full after the first check, which sets the clock.
    const glm::ivec3 dims{24, 24, 24};
    const std::vector<float> volume(countOf(dims), 0.0F);
    const LevelSetParams curvature{0.0F, 10.0F, 0.0F};
    const Sphere ball{glm::vec3(12.0F), 8.0F};
    SolverOptions o;
    o.settleIterations = 64;
    o.settleDisplacement = 1e9F;
    LevelSetSolver solver(volume, dims, o);
    solver.setParams(curvature);
    solver.addSphere(ball);
    StepResult r = solver.runUntilConverged(1000);
    EXPECT_EQ(r.stopReason, StopReason::Converged);
    EXPECT_EQ(r.iterations, 64 + o.checkInterval);
    // An edit restarts the window.
    solver.addSphere(ball);
    EXPECT_FALSE(solver.converged());
    r = solver.runUntilConverged(1000);
    EXPECT_EQ(r.stopReason, StopReason::Converged);
    EXPECT_EQ(r.iterations, 64 + o.checkInterval);
    // Off, or at the default tolerance: the ball runs to the cap while it shrinks (0.03 voxel
    // an iteration, 2 voxels a window).
    for (const int window : {0, 64}) {
        SolverOptions d;
        d.settleIterations = window;
        LevelSetSolver off(volume, dims, d);
        off.setParams(curvature);
        off.addSphere(ball);
        EXPECT_EQ(off.runUntilConverged(100).stopReason, StopReason::IterationLimit) << window;
    }
}

TEST_F(SolverStopTest, ASpillAlongAWideContactIsStoppedByTheRunawayWatch) {
    const std::vector<float> volume = ballBesideSlab();
    SolverOptions o;
    o.stopOnLeak = true;
    o.checkInterval = 4;
    LevelSetSolver solver(volume, kDims, o);
    solver.setParams(kParams);
    solver.addSphere({kBall, 3.0F});
    const StepResult r = solver.runUntilConverged(3000);
    ASSERT_EQ(r.stopReason, StopReason::Leak) << stopReasonName(r.stopReason);
    ASSERT_TRUE(r.leak.has_value());
    EXPECT_GT(r.leak->centre().x, kBall.x + kBallRadius - 2.0F);
    EXPECT_EQ(r.leak->sign, model::LeakSign::RunawayFill) << "a fill going on at its rate, no jump";
    const std::vector<std::uint8_t> mask = solver.readMask();
    const std::size_t slab = static_cast<std::size_t>(kDims.x - kSlabStart) * 32 * 32;
    EXPECT_LT(insideSlab(mask), slab / 4) << insideCount(mask);

    // The jump watch alone lets it fill the slab (49,871 voxels against 7,251 with the runaway
    // watch): the growth rate never falls and jumps again.
    o.runawayFactor = 0.0F;
    LevelSetSolver jumpOnly(volume, kDims, o);
    jumpOnly.setParams(kParams);
    jumpOnly.addSphere({kBall, 3.0F});
    const StepResult all = jumpOnly.runUntilConverged(3000);
    EXPECT_NE(all.stopReason, StopReason::Leak);
    EXPECT_GT(insideSlab(jumpOnly.readMask()), slab * 9 / 10);
}

// A kiosk steps a few iterations a frame, as many as its frame's share allows. The watches'
// checks still fall every checkInterval iterations of the run, counted from the step after the
// last change, so they see the same intervals and stop the same fill at the same check as one
// call does (before, a call's last iterations made a short interval of their own: the kiosk's
// stops depended on its frame rate).
TEST_F(SolverStopTest, ChecksFallAtTheSameIterationsHoweverTheCallsSplitTheRun) {
    const std::vector<float> volume = ballBesideSlab();
    SolverOptions o;
    o.stopOnLeak = true;
    o.checkInterval = 4; // the runaway test's: its fill stops within 3000 iterations
    std::vector<FrontCheck> checks;
    const auto run = [&](LevelSetSolver& solver, const std::vector<int>& calls, int limit) {
        checks.clear();
        StepResult r;
        int done = 0;
        for (std::size_t n = 0; r.stopReason != StopReason::Leak && done < limit; ++n) {
            r = solver.step(std::min(calls[n % calls.size()], limit - done));
            done += r.iterations;
        }
        return r.stopReason;
    };
    LevelSetSolver whole(volume, kDims, o);
    whole.setCheckObserver([&checks](const FrontCheck& c) { checks.push_back(c); });
    whole.setParams(kParams);
    whole.addSphere({kBall, 3.0F});
    ASSERT_EQ(run(whole, {3000}, 3000), StopReason::Leak);
    const std::vector<FrontCheck> wholeChecks = checks;

    LevelSetSolver frames(volume, kDims, o);
    frames.setCheckObserver([&checks](const FrontCheck& c) { checks.push_back(c); });
    frames.setParams(kParams);
    frames.addSphere({kBall, 3.0F});
    EXPECT_EQ(run(frames, {1, 7, 3, 4, 9, 2, 5}, 3000), StopReason::Leak);
    ASSERT_EQ(checks.size(), wholeChecks.size());
    for (std::size_t n = 0; n < checks.size(); ++n) {
        EXPECT_EQ(checks[n].iteration, wholeChecks[n].iteration) << "check " << n;
        EXPECT_EQ(checks[n].gained, wholeChecks[n].gained) << "check " << n;
        EXPECT_EQ(checks[n].lost, wholeChecks[n].lost) << "check " << n;
        EXPECT_EQ(checks[n].front, wholeChecks[n].front) << "check " << n;
    }
    EXPECT_EQ(frames.readMask(), whole.readMask());

    // After a change the checks count from the next step, not from the solver's first.
    frames.step(3);
    const int changedAt = frames.stats().iterations;
    frames.setParams(kParams);
    run(frames, {3, 2}, 12);
    ASSERT_EQ(checks.size(), 3U);
    for (std::size_t n = 0; n < checks.size(); ++n) {
        EXPECT_EQ(checks[n].iteration, changedAt + 4 * static_cast<int>(n + 1));
    }
}

} // namespace
} // namespace steerseg::test
