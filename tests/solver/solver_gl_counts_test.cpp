// What an iteration costs in GL calls (gpu/gl_counts, issue 50): a known run's dispatches,
// memory barriers and host synchronisations, counted the same on llvmpipe as on any GPU. The
// counts are the solver's structure, so a change that folds or adds a pass changes them here.
#include "gpu/gl_counts.hpp"
#include "model/solver_types.hpp"
#include "solver/level_set_solver.hpp"
#include "speed/classifier_speed.hpp"
#include "support/gpu_fixture.hpp"
#include "support/solver_test_support.hpp"

#include <gtest/gtest.h>

namespace steerseg::test {
namespace {

class SolverGlCountsTest : public GpuTest {};

constexpr glm::ivec3 kDims{48, 48, 48};
constexpr int kChecks = 4;

// A small front growing in a ball, past its first check (programs built, the pool sized).
struct GrowingFront {
    std::vector<float> volume = ballVolume(kDims, 0.0F, 100.0F, {24, 24, 24}, 14.0F);
    solver::LevelSetSolver solver{volume, kDims};
    int interval = model::SolverOptions{}.checkInterval;
    GrowingFront() {
        solver.addSphere({{24, 24, 24}, 3.0F});
        solver.setParams({100.0F, 30.0F, 0.8F});
        solver.step(interval);
    }
    // The calls of kChecks check intervals of iterations.
    gpu::GlCounts count() {
        const gpu::GlCounts before = gpu::glCounts();
        EXPECT_EQ(solver.step(kChecks * interval).iterations, kChecks * interval);
        return gpu::glCounts() - before;
    }
};

TEST_F(SolverGlCountsTest, AThresholdIterationIsFiveDispatchesEachBehindABarrier) {
    GrowingFront run;
    const gpu::GlCounts c = run.count();
    const auto iterations = static_cast<std::uint64_t>(kChecks * run.interval);
    // allocate_bricks, build_active_list, measure_speed, update_phi, settle_bricks: the
    // one-thread passes are the last groups of those around them (it was ten).
    EXPECT_EQ(c.dispatches, 5 * iterations);
    // One after each dispatch; the rest at the checks, around the host's reads and writes of
    // the control block.
    EXPECT_GE(c.barriers, c.dispatches);
    EXPECT_LE(c.barriers, c.dispatches + 8 * kChecks);
    // The host waits only at the checks, never between them: the control block, the leak
    // watch's counters, a pool growth (this run: 9 read-backs over 4 checks, no glFinish).
    EXPECT_EQ(c.finishes, 0U);
    EXPECT_GE(c.readBacks, static_cast<std::uint64_t>(kChecks));
    EXPECT_LE(c.readBacks, static_cast<std::uint64_t>(3 * kChecks));
}

// The new bricks' speed is evaluated where they are allocated, so only an iteration after a wake
// (the first after the speed was set: the warm-up step here) has a dispatch more.
TEST_F(SolverGlCountsTest, AClassifyIterationEvaluatesTheBricksTheFrontReachesInNoMore) {
    GrowingFront run;
    const std::vector<speed::Example> inside{{glm::vec3(24.0F), 4.0F}};
    const std::vector<speed::Example> outside{{glm::vec3(4.0F), 3.0F}};
    speed::ClassifierParams params;
    params.evaluation = speed::ClassifierEvaluation::OnDemand;
    params.trees = 4;
    const gpu::ScanTexture& scan = run.solver.scan();
    const speed::ClassifierSpeed classify(scan.exact(), kDims, inside, outside, params);
    run.solver.setSpeedInputs(
        {model::SpeedKind::Classify, 0, classify.texture(), classify.onDemandForest(), true});
    run.solver.step(run.interval);
    const std::uint32_t evaluated = run.solver.speedBricksEvaluated();
    const gpu::GlCounts c = run.count();
    const auto iterations = static_cast<std::uint64_t>(kChecks * run.interval);
    EXPECT_EQ(c.dispatches, 5 * iterations);
    EXPECT_GT(run.solver.speedBricksEvaluated(), evaluated) << "the growing front's new bricks";
    EXPECT_EQ(c.finishes, 0U);
    EXPECT_LE(c.readBacks, static_cast<std::uint64_t>(3 * kChecks));
}

TEST_F(SolverGlCountsTest, CountsAreTheCallingThreadsAndSubtract) {
    const gpu::GlCounts before = gpu::glCounts();
    gpu::memoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
    gpu::finish();
    gpu::countReadBack();
    const gpu::GlCounts d = gpu::glCounts() - before;
    EXPECT_EQ(d.dispatches, 0U);
    EXPECT_EQ(d.barriers, 1U);
    EXPECT_EQ(d.finishes, 1U);
    EXPECT_EQ(d.readBacks, 1U);
    EXPECT_EQ(d.hostSyncs(), 2U);
}

} // namespace
} // namespace steerseg::test
