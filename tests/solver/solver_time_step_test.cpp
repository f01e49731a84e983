// The time step's stability bound (TimeStepRule in app/solver/level_set_params.hpp): runs at
// both ends of alpha's range on a cube with a step edge stay bounded and do not oscillate. Both
// fail when the bound is loosened: alpha = 1 with the rescaling term's speed outside the
// Courant factor (dt -> 0.91 here: the seed's centre oscillates), alpha = 0 at twice the
// diffusion limit (every voxel flips).
#include "solver/level_set_solver.hpp"
#include "support/solver_test_support.hpp"
#include "support/gpu_fixture.hpp"

#include <algorithm>
#include <cmath>
#include <gtest/gtest.h>

namespace steerseg::test {
using namespace steerseg::solver; // the solver under test
using namespace steerseg::model;
namespace {

class SolverTimeStepTest : public GpuTest {};

constexpr glm::ivec3 kDims{40, 40, 40};
constexpr int kCubeLo = 12;
constexpr int kCubeHi = 28; // exclusive

bool inCube(int i, int j, int k) {
    return i >= kCubeLo && i < kCubeHi && j >= kCubeLo && j < kCubeHi && k >= kCubeLo &&
           k < kCubeHi;
}

// A cube of `inside` in `outside`: a step edge, with the cube's edges and corners.
std::vector<float> cubeVolume(float inside, float outside) {
    std::vector<float> v(countOf(kDims), outside);
    for (int k = 0; k < kDims.z; ++k) {
        for (int j = 0; j < kDims.y; ++j) {
            for (int i = 0; i < kDims.x; ++i) {
                if (inCube(i, j, k)) {
                    v[voxelIndex(kDims, i, j, k)] = inside;
                }
            }
        }
    }
    return v;
}

struct RunRecord {
    float maxAbsPhi = 0.0F;
    int mostSideChanges = 0;    // by one voxel over the run
    int sideReversals = 0;      // voxels that changed side and then changed back
    float lastMaxChange = 0.0F; // max |phi(n+1) - phi(n)| over the last 10 iterations
    // Voxels whose phi went up, down and up again (or the reverse) by more than 1e-3 per step:
    // an explicit step past its bound overshoots and swings back; a stable one relaxes
    // monotonically.
    int wigglingVoxels = 0;
};

// One iteration per call, phi read back after each.
RunRecord record(LevelSetSolver& s, int iterations) {
    RunRecord r;
    std::vector<float> prev = s.readPhi();
    std::vector<int> changes(prev.size(), 0);
    std::vector<float> lastDelta(prev.size(), 0.0F);
    std::vector<int> flips(prev.size(), 0);
    for (int n = 0; n < iterations; ++n) {
        EXPECT_EQ(s.step(1).iterations, 1);
        const std::vector<float> phi = s.readPhi();
        float maxChange = 0.0F;
        for (std::size_t v = 0; v < phi.size(); ++v) {
            r.maxAbsPhi = std::max(r.maxAbsPhi, std::abs(phi[v]));
            if ((phi[v] < 0.0F) != (prev[v] < 0.0F)) {
                ++changes[v];
            }
            const float delta = phi[v] - prev[v];
            maxChange = std::max(maxChange, std::abs(delta));
            if (std::abs(delta) > 1e-3F) {
                if (delta * lastDelta[v] < 0.0F) {
                    ++flips[v];
                }
                lastDelta[v] = delta;
            }
        }
        if (n >= iterations - 10) {
            r.lastMaxChange = std::max(r.lastMaxChange, maxChange);
        }
        prev = phi;
    }
    for (std::size_t v = 0; v < prev.size(); ++v) {
        r.mostSideChanges = std::max(r.mostSideChanges, changes[v]);
        r.sideReversals += changes[v] >= 2 ? 1 : 0;
        r.wigglingVoxels += flips[v] >= 3 ? 1 : 0;
    }
    std::printf("max|phi| %.3f, side changes <= %d, reversals %d, wiggling %d, last max change "
                "%.2e, t = %.3f after %d iterations\n",
                static_cast<double>(r.maxAbsPhi), r.mostSideChanges, r.sideReversals,
                r.wigglingVoxels, static_cast<double>(r.lastMaxChange),
                static_cast<double>(s.stats().evolvedTime), s.stats().iterations);
    return r;
}

// alpha = 1 with a low-contrast edge: |alpha D| on the front is small, so the step is the
// longest the rule allows at any alpha, set by the rescaling term. The seed grows to the cube's
// faces (8 voxels at speed 0.05) and stops there.
TEST_F(SolverTimeStepTest, AlphaOneOnALowContrastStepEdgeGrowsMonotonicallyAndSettles) {
    LevelSetSolver s(cubeVolume(1.0F, 0.9F), kDims);
    s.addSphere({{20.0F, 20.0F, 20.0F}, 3.0F});
    const LevelSetParams params{1.0F, 0.05F, 1.0F}; // D = +0.05 in the cube, -0.05 outside
    s.setParams(params);
    const RunRecord r = record(s, 600);
    EXPECT_LE(r.maxAbsPhi, kPhiFar);
    EXPECT_EQ(r.mostSideChanges, 1); // grows only
    EXPECT_EQ(r.wigglingVoxels, 0);
    EXPECT_LT(r.lastMaxChange, 1e-2F); // settled
    // The front stopped on the cube's faces: inside is the cube.
    const auto mask = s.readMask();
    EXPECT_EQ(mask[voxelIndex(kDims, kCubeLo, 20, 20)], 1);
    EXPECT_EQ(mask[voxelIndex(kDims, kCubeLo - 1, 20, 20)], 0);
    EXPECT_EQ(mask[voxelIndex(kDims, kCubeHi - 1, 20, 20)], 1);
    EXPECT_EQ(mask[voxelIndex(kDims, kCubeHi, 20, 20)], 0);
    const float dt = stableTimeStep(timeStepRule(params), 0.05F);
    EXPECT_LE(dt * (0.05F + kRescaleWeight * kPhiFar), 0.5F + 1e-6F);
}

// alpha = 0: curvature flow from the cube itself, whose edges and corners are the sharpest
// curvature the grid holds. It rounds and shrinks, so each voxel can only leave.
TEST_F(SolverTimeStepTest, AlphaZeroFromTheCubeShrinksMonotonically) {
    const auto volume = cubeVolume(1.0F, 0.9F);
    LevelSetSolver s(volume, kDims);
    std::vector<std::uint8_t> cube(countOf(kDims), 0);
    for (std::size_t v = 0; v < volume.size(); ++v) {
        cube[v] = volume[v] > 0.95F ? 1 : 0;
    }
    s.initFromMask(cube);
    const LevelSetParams params{1.0F, 0.05F, 0.0F};
    s.setParams(params);
    const RunRecord r = record(s, 120);
    EXPECT_LE(r.maxAbsPhi, kPhiFar);
    EXPECT_EQ(r.mostSideChanges, 1); // shrinks only
    EXPECT_EQ(r.wigglingVoxels, 0);
    const auto mask = s.readMask();
    EXPECT_EQ(mask[voxelIndex(kDims, 20, 20, 20)], 1); // not gone yet (t = 15 of ~25)
    EXPECT_EQ(mask[voxelIndex(kDims, kCubeLo, kCubeLo, kCubeLo)], 0); // the corner went first
    EXPECT_LE(stableTimeStep(timeStepRule(params), 0.0F), 1.0F / 6.0F);
}

} // namespace
} // namespace steerseg::test
