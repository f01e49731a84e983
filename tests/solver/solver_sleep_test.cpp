// Sleeping bricks (docs/solver.md, "Sleeping bricks"): a brick whose phi stopped moving is left
// out of the step's passes until a neighbour's face, an edit or a parameter change wakes it. Each
// case runs the same script with sleeping on and off: the masks must agree (Dice >= 0.995, and
// the voxels that only a woken brick can reach must be reached), and where most of the front has
// stopped the sleeping run must visit fewer voxels.
#include "solver/level_set_solver.hpp"
#include "support/gpu_fixture.hpp"
#include "support/solver_test_support.hpp"

#include <cstdio>
#include <functional>
#include <gtest/gtest.h>

namespace steerseg::test {
using namespace steerseg::solver; // the solver under test
using namespace steerseg::model;
namespace {

class SolverSleepTest : public GpuTest {};

struct SleepRun {
    std::vector<std::uint8_t> mask;
    SolverStats stats;
};

// Runs `script` on a fresh solver over `volume`, with sleeping on or off.
SleepRun runScript(const std::vector<float>& volume, const glm::ivec3& d, bool sleep,
                   const std::function<void(LevelSetSolver&)>& script) {
    SolverOptions options;
    options.sleep = sleep;
    LevelSetSolver s(volume, d, options);
    script(s);
    return {s.readMask(), s.stats()};
}

void report(const char* name, const SleepRun& asleep, const SleepRun& awake) {
    std::printf("%s: Dice %.5f, visited/iteration %.0f (sleeping) vs %.0f, front %u, awake %u "
                "of %u bricks\n",
                name, dice(asleep.mask, awake.mask), asleep.stats.visitedVoxelsPerIteration,
                awake.stats.visitedVoxelsPerIteration, asleep.stats.frontVoxels,
                asleep.stats.activeBricks, asleep.stats.bandBricks);
}

// Regions of intensity 1 in 0: with T = 1 the speed is eps inside and eps - 1 outside, so a
// seed in one fills it and stops at its edge (eps 0.9: faster inside, a weaker stop).
LevelSetParams edgeParams(float eps = 0.5F) {
    LevelSetParams p;
    p.T = 1.0F;
    p.eps = eps;
    p.alpha = 0.8F;
    return p;
}

TEST_F(SolverSleepTest, StoppedFrontSleepsAndKeepsTheMask) {
    const glm::ivec3 d(40, 40, 40);
    const auto volume = ballVolume(d, 0.0F, 1.0F, glm::vec3(20.0F), 10.0F);
    auto script = [](LevelSetSolver& s) {
        s.addSphere({glm::vec3(20.0F), 3.0F});
        s.setParams(edgeParams());
        s.step(320);
    };
    const SleepRun asleep = runScript(volume, d, true, script);
    const SleepRun awake = runScript(volume, d, false, script);
    report("ball", asleep, awake);
    EXPECT_GE(dice(asleep.mask, awake.mask), 0.995);
    EXPECT_GT(insideCount(asleep.mask), 3000U); // it grew to the ball (4189 voxels)
    // Stopped everywhere: most bricks sleep, and the run visited fewer voxels.
    EXPECT_LT(asleep.stats.activeBricks * 2, asleep.stats.bandBricks);
    EXPECT_LT(asleep.stats.visitedVoxelsPerIteration, 0.8 * awake.stats.visitedVoxelsPerIteration);
    EXPECT_EQ(awake.stats.activeBricks, awake.stats.bandBricks);
}

// Every brick asleep means nothing can change: runUntilConverged stops there, with the mask the
// side-change rule reaches without sleeping.
TEST_F(SolverSleepTest, EveryBrickAsleepIsConverged) {
    const glm::ivec3 d(32, 32, 32);
    const auto volume = ballVolume(d, 0.0F, 1.0F, glm::vec3(16.0F), 7.0F);
    int asleepIterations = 0;
    int awakeIterations = 0;
    auto script = [](int& iterations) {
        return [&iterations](LevelSetSolver& s) {
            s.addSphere({glm::vec3(16.0F), 3.0F});
            s.setParams(edgeParams());
            const StepResult r = s.runUntilConverged(4000);
            EXPECT_EQ(r.stopReason, StopReason::Converged);
            iterations = r.iterations;
        };
    };
    const SleepRun asleep = runScript(volume, d, true, script(asleepIterations));
    const SleepRun awake = runScript(volume, d, false, script(awakeIterations));
    report("converged", asleep, awake);
    std::printf("converged after %d iterations (sleeping) vs %d\n", asleepIterations,
                awakeIterations);
    EXPECT_EQ(asleep.stats.activeBricks, 0U);
    EXPECT_GE(dice(asleep.mask, awake.mask), 0.995);
}

// A tube along x: the front stops at the wall within a few iterations and runs on along the
// axis; only the bricks at the tip need to stay awake.
TEST_F(SolverSleepTest, FrontStoppedSidewaysSleepsWhileTheTipMoves) {
    const glm::ivec3 d(64, 24, 24);
    std::vector<float> volume(countOf(d), 0.0F);
    for (int k = 0; k < d.z; ++k) {
        for (int j = 0; j < d.y; ++j) {
            for (int i = 2; i < d.x - 2; ++i) {
                if (glm::length(glm::vec2(j - 12, k - 12)) <= 5.0F) {
                    volume[voxelIndex(d, i, j, k)] = 1.0F;
                }
            }
        }
    }
    auto script = [](LevelSetSolver& s) {
        s.addSphere({glm::vec3(6.0F, 12.0F, 12.0F), 3.0F});
        s.setParams(edgeParams(0.9F));
        s.step(300);
    };
    const SleepRun asleep = runScript(volume, d, true, script);
    const SleepRun awake = runScript(volume, d, false, script);
    report("tube", asleep, awake);
    EXPECT_GE(dice(asleep.mask, awake.mask), 0.995);
    // Measured: 37 of 64 bricks awake at the end, 17.6k voxels visited per iteration vs 21.2k
    // (the run is mostly the tip's advance).
    EXPECT_LT(asleep.stats.activeBricks * 4, asleep.stats.bandBricks * 3);
    EXPECT_LT(asleep.stats.visitedVoxelsPerIteration, 0.9 * awake.stats.visitedVoxelsPerIteration);
}

// After the ball's front stopped (and slept), a wider window (eps) makes the background grow:
// setParams must wake the sleeping bricks.
TEST_F(SolverSleepTest, ParameterChangeWakesTheStoppedFront) {
    const glm::ivec3 d(40, 40, 40);
    const auto volume = ballVolume(d, 0.0F, 1.0F, glm::vec3(20.0F), 8.0F);
    auto script = [](LevelSetSolver& s) {
        s.addSphere({glm::vec3(20.0F), 3.0F});
        s.setParams(edgeParams());
        s.step(200);
        LevelSetParams wider = edgeParams();
        wider.eps = 1.3F; // background: D = 0.3
        s.setParams(wider);
        s.step(16);
    };
    const SleepRun asleep = runScript(volume, d, true, script);
    const SleepRun awake = runScript(volume, d, false, script);
    report("parameter change", asleep, awake);
    EXPECT_GE(dice(asleep.mask, awake.mask), 0.995);
    // It grew past the ball (2109 voxels) after the change, in both runs.
    EXPECT_GT(insideCount(asleep.mask), 2500U);
    EXPECT_GT(insideCount(awake.mask), 2500U);
}

// Two balls side by side: the first fills and sleeps; a seed in the second (whose band touches
// the first's sleeping bricks) grows, and an eraser cuts into the far side of the sleeping first
// ball, where no neighbour's motion reaches: only the edit's wake lets the cut refill (without
// it: Dice 0.991).
TEST_F(SolverSleepTest, SeedAndEraserNextToASleepingRegion) {
    const glm::ivec3 d(56, 32, 32);
    auto volume = ballVolume(d, 0.0F, 1.0F, glm::vec3(16.0F, 16.0F, 16.0F), 8.0F);
    const auto second = ballVolume(d, 0.0F, 1.0F, glm::vec3(36.0F, 16.0F, 16.0F), 8.0F);
    for (std::size_t n = 0; n < volume.size(); ++n) {
        volume[n] = std::max(volume[n], second[n]);
    }
    auto script = [](LevelSetSolver& s) {
        s.addSphere({glm::vec3(16.0F, 16.0F, 16.0F), 3.0F});
        s.setParams(edgeParams());
        s.step(200);
        s.addSphere({glm::vec3(36.0F, 16.0F, 16.0F), 3.0F});
        s.removeSphere({glm::vec3(9.0F, 16.0F, 16.0F), 3.0F});
        s.step(120);
    };
    const SleepRun asleep = runScript(volume, d, true, script);
    const SleepRun awake = runScript(volume, d, false, script);
    report("seed and eraser", asleep, awake);
    EXPECT_GE(dice(asleep.mask, awake.mask), 0.995);
}

// A front that arrives at a sleeping brick from its neighbour: the first ball's band is stored in
// a brick (x 24..31) that sleeps once the ball is full; a tube from the far end, separate from
// the ball by two voxels, brings a second front into that brick. Only a neighbour's wake lets it
// fill the tube's voxels there.
TEST_F(SolverSleepTest, FrontArrivingFromANeighbourWakesASleepingBrick) {
    const glm::ivec3 d(64, 32, 32);
    auto volume = ballVolume(d, 0.0F, 1.0F, glm::vec3(16.0F, 16.0F, 16.0F), 8.0F);
    for (int k = 0; k < d.z; ++k) {
        for (int j = 0; j < d.y; ++j) {
            for (int i = 27; i < 62; ++i) {
                if (glm::length(glm::vec2(j - 16, k - 16)) <= 4.0F) {
                    volume[voxelIndex(d, i, j, k)] = 1.0F;
                }
            }
        }
    }
    auto script = [](LevelSetSolver& s) {
        s.addSphere({glm::vec3(16.0F, 16.0F, 16.0F), 3.0F});
        s.setParams(edgeParams(0.9F));
        s.step(100);
        // Not an edit near the first ball: the second seed sits at the tube's far end.
        s.addSphere({glm::vec3(56.0F, 16.0F, 16.0F), 2.0F});
        s.step(240);
    };
    const SleepRun asleep = runScript(volume, d, true, script);
    const SleepRun awake = runScript(volume, d, false, script);
    report("arriving front", asleep, awake);
    EXPECT_GE(dice(asleep.mask, awake.mask), 0.995);
    // The tube's voxels in the brick that slept are inside in both runs.
    for (int i = 28; i < 32; ++i) {
        EXPECT_EQ(awake.mask[voxelIndex(d, i, 16, 16)], 1) << "x " << i;
        EXPECT_EQ(asleep.mask[voxelIndex(d, i, 16, 16)], 1) << "x " << i;
    }
}

} // namespace
} // namespace steerseg::test
