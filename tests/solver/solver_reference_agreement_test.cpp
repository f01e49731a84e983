// GPU sparse solver against the dense CPU reference on synthetic volumes.
#include "solver/level_set_solver.hpp"
#include "solver/reference_solver.hpp"
#include "support/gpu_fixture.hpp"
#include "support/solver_test_support.hpp"

#include <gtest/gtest.h>

namespace steerseg::test {
using namespace steerseg::solver; // the solver under test
using namespace steerseg::model;
namespace {

class SolverAgreementTest : public GpuTest {};

void expectAgree(const glm::ivec3& d, const std::vector<std::uint8_t>& gpu,
                 const std::vector<std::uint8_t>& cpu) {
    ASSERT_EQ(gpu.size(), cpu.size());
    EXPECT_GT(insideCount(cpu), 0U);
    EXPECT_GE(dice(gpu, cpu), 0.99) << "gpu " << insideCount(gpu) << " cpu " << insideCount(cpu);
    EXPECT_EQ(differencesOffSurface(d, gpu, cpu), 0U);
}

TEST_F(SolverAgreementTest, GrowingBallMatchesReference) {
    const glm::ivec3 d{48, 44, 40};
    const auto volume = ballVolume(d, 0.0F, 100.0F, {24, 22, 20}, 15.0F);
    const LevelSetParams params{100.0F, 30.0F, 0.7F};
    const Sphere seed{{22, 20, 19}, 4.0F};
    LevelSetSolver gpu(volume, d);
    gpu.addSphere(seed);
    gpu.setParams(params);
    ReferenceSolver cpu(volume, d);
    cpu.addSphere(seed);
    cpu.setParams(params);
    const StepResult r = gpu.step(60);
    EXPECT_EQ(r.iterations, 60);
    EXPECT_EQ(cpu.step(60), 60);
    EXPECT_NEAR(r.evolvedTime, cpu.evolvedTime(), 1e-3F * cpu.evolvedTime());
    expectAgree(d, gpu.readMask(), cpu.mask());
}

// The GPU solver and the reference from the same seed and parameters, stepped together.
struct SolverPair {
    LevelSetSolver gpu;
    ReferenceSolver cpu;
    SolverPair(const std::vector<float>& volume, const glm::ivec3& d, const Sphere& seed,
               const LevelSetParams& params)
        : gpu(volume, d), cpu(volume, d) {
        gpu.addSphere(seed);
        cpu.addSphere(seed);
        setParams(params);
    }
    void setParams(const LevelSetParams& params) {
        gpu.setParams(params);
        cpu.setParams(params);
    }
    void step(int n) {
        gpu.step(n);
        cpu.step(n);
    }
};

// Each brick keeps its speeds between steps (shaders/solver/speed_cache.glsl); a change of T and
// eps must reach them. The second window refuses the ball, so the front that grew into it
// shrinks back; with the speeds of the first it would go on growing.
TEST_F(SolverAgreementTest, ANewWindowMidRunMatchesReference) {
    const glm::ivec3 d{48, 44, 40};
    const auto volume = ballVolume(d, 0.0F, 100.0F, {24, 22, 20}, 15.0F);
    SolverPair run(volume, d, {{22, 20, 19}, 4.0F}, {100.0F, 30.0F, 0.7F});
    run.step(40);
    const std::size_t grown = insideCount(run.cpu.mask());
    run.setParams({50.0F, 10.0F, 0.7F});
    run.step(20);
    EXPECT_LT(insideCount(run.cpu.mask()), grown);
    expectAgree(d, run.gpu.readMask(), run.cpu.mask());
}

// A shrink moves bricks to lower slots, where the speeds kept are another brick's (or none):
// the tags must send each moved brick back to measure_speed. A seed larger than a bright ball
// retreats onto it and the pool shrinks under the front, which then goes on stepping where
// the speed changes sign; with a neighbour's speeds a moved brick's front would drift.
TEST_F(SolverAgreementTest, AfterThePoolShrankUnderTheFrontMatchesReference) {
    const glm::ivec3 d{64, 64, 56};
    const auto volume = ballVolume(d, 0.0F, 100.0F, {32, 32, 28}, 13.0F);
    SolverPair run(volume, d, {{32, 32, 28}, 21.0F}, {100.0F, 30.0F, 0.7F});
    run.step(48);
    ASSERT_GE(run.gpu.stats().poolShrinks, 1);
    run.step(32);
    expectAgree(d, run.gpu.readMask(), run.cpu.mask());
}

} // namespace
} // namespace steerseg::test
