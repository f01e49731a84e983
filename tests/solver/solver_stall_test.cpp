// The pool-stall path (the band outruns the free slots between two pool checks) and the stop
// reason of the step calls.
#include "solver/level_set_solver.hpp"
#include "support/solver_test_support.hpp"
#include "support/gpu_fixture.hpp"

#include <gtest/gtest.h>

namespace steerseg::test {
using namespace steerseg::solver; // the solver under test
using namespace steerseg::model;
namespace {

class SolverStallTest : public GpuTest {};

// Uniform intensity inside the range: a small seed grows at speed eps in every direction, so
// the band gains a shell of bricks every few iterations.
constexpr glm::ivec3 kDims{48, 48, 40};
const LevelSetParams kGrow{100.0F, 5.0F, 1.0F};
const Sphere kSeed{{24.0F, 24.0F, 20.0F}, 2.0F};

std::vector<float> uniformVolume() {
    return std::vector<float>(countOf(kDims), 100.0F);
}

// With one pool check per 64 iterations the band needs far more bricks between two checks than
// the margin left at the last one: allocate_bricks sets `stalled`, the stalled iterations take
// no step, and the host grows the pool and runs them again. With a check every iteration the
// margin always suffices. Both must end with the same phi.
TEST_F(SolverStallTest, BandOutrunningThePoolStallsGrowsAndEndsLikeARunWithoutStalls) {
    const auto volume = uniformVolume();
    SolverOptions rare;
    rare.checkInterval = 64;
    SolverOptions often;
    often.checkInterval = 1;
    LevelSetSolver stalling(volume, kDims, rare);
    LevelSetSolver steady(volume, kDims, often);
    for (LevelSetSolver* s : {&stalling, &steady}) {
        s->addSphere(kSeed);
        s->setParams(kGrow);
    }
    const std::uint32_t firstCapacity = stalling.stats().capacity;
    const StepResult a = stalling.step(48);
    const StepResult b = steady.step(48);
    EXPECT_EQ(a.iterations, 48); // stalled iterations are re-run, not lost
    EXPECT_EQ(b.iterations, 48);

    const SolverStats s = stalling.stats();
    std::printf("check every 64: capacity %u -> %u, %d growths, %d stalls, peak %u bricks\n",
                firstCapacity, s.capacity, s.poolGrowths, s.stalls, s.peakActiveBricks);
    EXPECT_GT(s.stalls, 0);
    EXPECT_GE(s.poolGrowths, s.stalls);
    EXPECT_GT(s.capacity, firstCapacity);
    EXPECT_GT(s.peakActiveBricks, 4 * firstCapacity); // the band did outgrow the first pool
    EXPECT_EQ(steady.stats().stalls, 0);

    EXPECT_EQ(a.evolvedTime, b.evolvedTime);
    EXPECT_EQ(stalling.readPhi(), steady.readPhi());
}

TEST_F(SolverStallTest, StepCallsReportWhyTheyStopped) {
    const auto volume = uniformVolume();
    LevelSetSolver gpu(volume, kDims);
    gpu.addSphere(kSeed);
    gpu.setParams(kGrow);

    const StepResult stepped = gpu.step(5);
    EXPECT_EQ(stepped.iterations, 5);
    EXPECT_EQ(stepped.stopReason, StopReason::IterationLimit);

    const StepResult timed = gpu.evolveUntil(stepped.evolvedTime + 1.0F, 1000);
    EXPECT_EQ(timed.stopReason, StopReason::TimeReached);
    EXPECT_FLOAT_EQ(timed.evolvedTime, stepped.evolvedTime + 1.0F);
    EXPECT_LT(timed.iterations, 1000);

    // Out of iterations before the time.
    const StepResult cut = gpu.evolveUntil(timed.evolvedTime + 100.0F, 3);
    EXPECT_EQ(cut.iterations, 3);
    EXPECT_EQ(cut.stopReason, StopReason::IterationLimit);

    // Still growing: not converged within 4 iterations.
    const StepResult growing = gpu.runUntilConverged(4);
    EXPECT_EQ(growing.stopReason, StopReason::IterationLimit);
    EXPECT_FALSE(growing.converged);

    // A surface with no speed (alpha = 1, D = 0) never changes side: converged.
    gpu.setParams({100.0F, 0.0F, 1.0F});
    const StepResult still = gpu.runUntilConverged(2000);
    EXPECT_TRUE(still.converged);
    EXPECT_EQ(still.stopReason, StopReason::Converged);
    EXPECT_LT(still.iterations, 2000);

    EXPECT_STREQ(stopReasonName(StopReason::Converged), "converged");
    EXPECT_STREQ(stopReasonName(StopReason::TimeReached), "time_reached");
    EXPECT_STREQ(stopReasonName(StopReason::IterationLimit), "iteration_limit");
}

} // namespace
} // namespace steerseg::test
