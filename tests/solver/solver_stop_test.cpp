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

} // namespace
} // namespace steerseg::test
