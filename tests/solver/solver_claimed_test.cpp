// Voxels other structures hold (LevelSetSolver::setClaimed, shaders/solver/barrier_speed.glsl):
// the speed blocks there, so a front in a uniform region grows up to a claimed slab and never
// into it, a seed over claimed voxels recedes from them, and without the mask the front grows
// through. The mask is the solver's, not the level set's: copies and parameters leave it. Kept
// voxels (LevelSetSolver::setKept, what an erase's run may not take back) are their mirror: a
// surface the speed takes back everywhere withdraws to them and no further.
#include "solver/level_set_solver.hpp"
#include "support/gpu_fixture.hpp"
#include "support/solver_test_support.hpp"

#include <algorithm>
#include <gtest/gtest.h>

namespace steerseg::test {
using namespace steerseg::solver; // the solver under test
using namespace steerseg::model;
namespace {

class SolverClaimedTest : public GpuTest {};

// 50 voxels along i: two packed words a row, the slab across the boundary between them.
constexpr glm::ivec3 kDims{50, 36, 28};
constexpr int kSlabLo = 30;
constexpr int kSlabHi = 33;
const LevelSetParams kParams{100.0F, 40.0F, 0.9F};

std::vector<float> uniformRegion() {
    return std::vector<float>(countOf(kDims), 100.0F);
}

// Claimed: every voxel with kSlabLo <= i <= kSlabHi, a wall across the whole scan.
std::vector<std::uint8_t> slab() {
    std::vector<std::uint8_t> m(countOf(kDims), 0);
    for (int k = 0; k < kDims.z; ++k) {
        for (int j = 0; j < kDims.y; ++j) {
            for (int i = kSlabLo; i <= kSlabHi; ++i) {
                m[voxelIndex(kDims, i, j, k)] = 1;
            }
        }
    }
    return m;
}

struct Counts {
    std::size_t below = 0;      // inside, i < kSlabLo
    std::size_t claimed = 0;    // inside the slab
    std::size_t beyond = 0;     // inside, i > kSlabHi
    std::size_t nextToSlab = 0; // inside at i = kSlabLo - 2
};

Counts count(const std::vector<std::uint8_t>& mask) {
    Counts c;
    for (int k = 0; k < kDims.z; ++k) {
        for (int j = 0; j < kDims.y; ++j) {
            for (int i = 0; i < kDims.x; ++i) {
                if (mask[voxelIndex(kDims, i, j, k)] == 0) {
                    continue;
                }
                if (i < kSlabLo) {
                    ++c.below;
                    c.nextToSlab += i == kSlabLo - 2 ? 1 : 0;
                } else if (i <= kSlabHi) {
                    ++c.claimed;
                } else {
                    ++c.beyond;
                }
            }
        }
    }
    return c;
}

TEST_F(SolverClaimedTest, TheFrontGrowsUpToAClaimedSlabAndNeverIntoIt) {
    LevelSetSolver solver(uniformRegion(), kDims);
    solver.setParams(kParams);
    solver.setClaimed(slab());
    EXPECT_TRUE(solver.hasClaimed());
    solver.addSphere({{15.0F, 18.0F, 14.0F}, 3.0F});
    EXPECT_EQ(solver.runUntilConverged(3000).stopReason, StopReason::Converged);
    const Counts grown = count(solver.readMask());
    EXPECT_EQ(grown.claimed, 0U);
    EXPECT_EQ(grown.beyond, 0U);
    // Up to it: nearly the whole plane two voxels short of the slab.
    const auto plane = static_cast<std::size_t>(kDims.y * kDims.z);
    EXPECT_GT(grown.nextToSlab, plane * 7 / 10) << grown.nextToSlab << " of " << plane;

    // Not the level set's state: a restored copy and new parameters step against it still.
    const LevelSetCopy copy = solver.copyLevelSet();
    solver.setParams({100.0F, 40.0F, 0.8F});
    solver.restoreLevelSet(copy);
    EXPECT_TRUE(solver.hasClaimed());
    solver.step(300);
    const Counts kept = count(solver.readMask());
    EXPECT_EQ(kept.claimed, 0U);
    EXPECT_EQ(kept.beyond, 0U);

    solver.setClaimed({});
    EXPECT_FALSE(solver.hasClaimed());
    EXPECT_EQ(solver.runUntilConverged(3000).stopReason, StopReason::Converged);
    const Counts through = count(solver.readMask());
    EXPECT_GT(through.claimed, 0U) << "cleared, the front grows through";
    EXPECT_GT(through.beyond, 0U);
}

TEST_F(SolverClaimedTest, ASeedOverClaimedVoxelsRecedesFromThem) {
    LevelSetSolver solver(uniformRegion(), kDims);
    solver.setParams(kParams);
    solver.setClaimed(slab());
    solver.addSphere({{31.5F, 18.0F, 14.0F}, 6.0F});
    ASSERT_GT(count(solver.readMask()).claimed, 0U);
    EXPECT_EQ(solver.runUntilConverged(3000).stopReason, StopReason::Converged);
    const Counts c = count(solver.readMask());
    EXPECT_EQ(c.claimed, 0U);
    // What lay on either side stays and grows.
    EXPECT_GT(c.below, 0U);
    EXPECT_GT(c.beyond, 0U);
}

TEST_F(SolverClaimedTest, RefusesAMaskOfAnotherSizeAndTakesNoneForAnEmptyOne) {
    LevelSetSolver solver(uniformRegion(), kDims);
    EXPECT_THROW(solver.setClaimed(std::vector<std::uint8_t>(countOf(kDims) - 1, 1)),
                 std::invalid_argument);
    EXPECT_FALSE(solver.hasClaimed());
    solver.setClaimed(std::vector<std::uint8_t>(countOf(kDims), 0));
    EXPECT_FALSE(solver.hasClaimed()) << "nothing claimed costs no texture";
    solver.setClaimed(slab());
    EXPECT_TRUE(solver.hasClaimed());
    EXPECT_THROW(solver.setClaimed(std::vector<std::uint8_t>(countOf(kDims) + 1, 0)),
                 std::invalid_argument);
    EXPECT_TRUE(solver.hasClaimed()) << "a refused mask leaves the one in force";
}

// The region reads far outside the window: without kept voxels the surface withdraws to nothing;
// with a ball of them it withdraws to the ball, holds every voxel of it and nothing two voxels
// beyond; released, it withdraws on.
TEST_F(SolverClaimedTest, ASurfaceTheSpeedTakesBackWithdrawsToKeptVoxelsAndNoFurther) {
    LevelSetSolver solver(uniformRegion(), kDims);
    solver.setParams({300.0F, 40.0F, 0.9F});
    const glm::vec3 centre{25.0F, 18.0F, 14.0F};
    std::vector<std::uint8_t> ball(countOf(kDims), 0);
    for (int k = 0; k < kDims.z; ++k) {
        for (int j = 0; j < kDims.y; ++j) {
            for (int i = 0; i < kDims.x; ++i) {
                if (glm::length(glm::vec3(i, j, k) - centre) <= 4.0F) {
                    ball[voxelIndex(kDims, i, j, k)] = 1;
                }
            }
        }
    }
    solver.addSphere({centre, 10.0F});
    solver.setKept(ball);
    EXPECT_TRUE(solver.hasKept());
    EXPECT_EQ(solver.runUntilConverged(3000).stopReason, StopReason::Converged);
    const std::vector<std::uint8_t> held = solver.readMask();
    std::size_t keptOutside = 0;
    std::size_t beyond = 0;
    for (int k = 0; k < kDims.z; ++k) {
        for (int j = 0; j < kDims.y; ++j) {
            for (int i = 0; i < kDims.x; ++i) {
                const std::size_t v = voxelIndex(kDims, i, j, k);
                keptOutside += ball[v] != 0 && held[v] == 0 ? 1 : 0;
                beyond += held[v] != 0 && glm::length(glm::vec3(i, j, k) - centre) > 6.0F ? 1 : 0;
            }
        }
    }
    EXPECT_EQ(keptOutside, 0U);
    EXPECT_EQ(beyond, 0U);

    solver.setKept({});
    EXPECT_FALSE(solver.hasKept());
    solver.step(300);
    const std::vector<std::uint8_t> released = solver.readMask();
    EXPECT_EQ(
        std::count_if(released.begin(), released.end(), [](std::uint8_t v) { return v != 0; }), 0)
        << "released, the surface withdraws on";
    EXPECT_THROW(solver.setKept(std::vector<std::uint8_t>(countOf(kDims) - 1, 1)),
                 std::invalid_argument);
}

} // namespace
} // namespace steerseg::test
