// The GPU sparse solver against closed-form motions.
#include "solver/level_set_solver.hpp"
#include "solver/reference_solver.hpp"
#include "support/gpu_fixture.hpp"
#include "support/solver_test_support.hpp"

#include <gtest/gtest.h>

namespace steerseg::test {
using namespace steerseg::solver; // the solver under test
using namespace steerseg::model;
namespace {

class SolverAnalyticTest : public GpuTest {};

TEST_F(SolverAnalyticTest, SeedInUniformInsideRegionGrowsAtSpeedEps) {
    const glm::ivec3 d{40, 40, 40};
    LevelSetSolver s(std::vector<float>(countOf(d), 100.0F), d);
    s.addSphere({{20, 20, 20}, 5.0F});
    s.setParams({100.0F, 2.0F, 1.0F}); // D = 2 voxels per unit time everywhere
    const StepResult r = s.evolveUntil(5.0F, 1000);
    EXPECT_FLOAT_EQ(r.evolvedTime, 5.0F);
    EXPECT_NEAR(equivalentRadius(s.readMask()), 15.0, 0.6);
}

TEST_F(SolverAnalyticTest, CurvatureFlowShrinksSphereAsRSquaredMinus4t) {
    const glm::ivec3 d{32, 32, 32};
    LevelSetSolver s(std::vector<float>(countOf(d), 0.0F), d);
    s.addSphere({{16, 16, 16}, 10.0F});
    s.setParams({0.0F, 0.0F, 0.0F}); // alpha = 0
    s.evolveUntil(16.0F, 1000);
    EXPECT_NEAR(equivalentRadius(s.readMask()), 6.0, 0.3); // sqrt(100 - 4 * 16)
}

TEST_F(SolverAnalyticTest, SeedOutsideTheRangeShrinksAwayAndFreesItsBricks) {
    const glm::ivec3 d{40, 40, 40};
    LevelSetSolver s(std::vector<float>(countOf(d), 0.0F), d);
    s.addSphere({{20, 20, 20}, 12.0F});
    s.setParams({100.0F, 10.0F, 1.0F}); // D = -90: the surface retreats
    s.step(16);
    const SolverStats grown = s.stats();
    EXPECT_GT(grown.activeBricks, 0U);
    s.evolveUntil(1.0F, 500);
    EXPECT_EQ(insideCount(s.readMask()), 0U);
    s.step(32); // lets the last bricks retire and the pool shrink at a check
    const SolverStats gone = s.stats();
    EXPECT_EQ(gone.activeBricks, 0U);
    EXPECT_LT(gone.levelSetBytes, grown.levelSetBytes);
    EXPECT_GE(gone.poolShrinks, 1);
}

TEST_F(SolverAnalyticTest, RemovedSphereCutsAHole) {
    const glm::ivec3 d{36, 36, 36};
    const std::vector<float> volume(countOf(d), 0.0F);
    LevelSetSolver s(volume, d);
    s.addSphere({{18, 18, 18}, 12.0F});
    s.removeSphere({{18, 18, 18}, 5.0F});
    const auto mask = s.readMask();
    EXPECT_EQ(mask[voxelIndex(d, 18, 18, 18)], 0);
    EXPECT_EQ(mask[voxelIndex(d, 21, 18, 18)], 0);
    EXPECT_EQ(mask[voxelIndex(d, 26, 18, 18)], 1);
    EXPECT_EQ(mask[voxelIndex(d, 18, 31, 18)], 0);
    ReferenceSolver cpu(volume, d);
    cpu.addSphere({{18, 18, 18}, 12.0F});
    cpu.removeSphere({{18, 18, 18}, 5.0F});
    EXPECT_EQ(mask, cpu.mask());
}

} // namespace
} // namespace steerseg::test
