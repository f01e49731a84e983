// Barriers and the leak watch on a structure that leaks: two balls of the same intensity joined
// by a thin tube, as a tumour touches a vessel or an organ of its intensity through a narrow
// neck. The threshold speed alone fills both.
#include "solver/level_set_solver.hpp"
#include "support/gpu_fixture.hpp"
#include "support/solver_test_support.hpp"

#include <gtest/gtest.h>

namespace steerseg::test {
using namespace steerseg::solver; // the solver under test
using namespace steerseg::model;
namespace {

class SolverLeakTest : public GpuTest {};

constexpr glm::ivec3 kDims{72, 32, 32};
constexpr glm::vec3 kBallA{16.0F, 16.0F, 16.0F};
constexpr glm::vec3 kBallB{54.0F, 16.0F, 16.0F};
constexpr float kBallRadius = 11.0F;
constexpr float kNeckRadius = 1.6F;
constexpr float kNeckMiddleX = 35.0F;
const LevelSetParams kParams{100.0F, 40.0F, 0.9F};
// Voxels of one ball.
constexpr auto kBallVoxels =
    static_cast<std::size_t>(4.19F * kBallRadius * kBallRadius * kBallRadius);

std::vector<float> dumbbell() {
    std::vector<float> v = ballVolume(kDims, 0.0F, 100.0F, kBallA, kBallRadius);
    for (int k = 0; k < kDims.z; ++k) {
        for (int j = 0; j < kDims.y; ++j) {
            for (int i = 0; i < kDims.x; ++i) {
                const glm::vec3 p(i, j, k);
                const bool tube =
                    p.x >= kBallA.x && p.x <= kBallB.x &&
                    glm::length(glm::vec2(p.y, p.z) - glm::vec2(16.0F)) <= kNeckRadius;
                if (tube || glm::length(p - kBallB) <= kBallRadius) {
                    v[voxelIndex(kDims, i, j, k)] = 100.0F;
                }
            }
        }
    }
    return v;
}

// Voxels inside ball B's half of the volume (beyond the neck's middle).
std::size_t insideBeyondNeck(const std::vector<std::uint8_t>& mask) {
    std::size_t n = 0;
    for (int k = 0; k < kDims.z; ++k) {
        for (int j = 0; j < kDims.y; ++j) {
            for (int i = static_cast<int>(kNeckMiddleX) + 1; i < kDims.x; ++i) {
                n += mask[voxelIndex(kDims, i, j, k)];
            }
        }
    }
    return n;
}

std::uint8_t inAt(const std::vector<std::uint8_t>& mask, glm::vec3 p) {
    return mask[voxelIndex(kDims, static_cast<int>(p.x), static_cast<int>(p.y),
                           static_cast<int>(p.z))];
}

SolverOptions watching() {
    SolverOptions o;
    o.stopOnLeak = true;
    o.checkInterval = 4; // the balls fill in a few dozen iterations
    return o;
}

TEST_F(SolverLeakTest, StopsWhenTheFrontBreaksThroughTheNeckAndSaysWhere) {
    const std::vector<float> volume = dumbbell();
    LevelSetSolver solver(volume, kDims, watching());
    solver.setParams(kParams);
    solver.addSphere({kBallA, 3.0F});
    const StepResult r = solver.runUntilConverged(3000);
    ASSERT_EQ(r.stopReason, StopReason::Leak) << stopReasonName(r.stopReason);
    ASSERT_TRUE(r.leak.has_value());
    EXPECT_EQ(r.leak->sign, model::LeakSign::GrowthJump) << "the jump through the neck";
    // The site is where the front grew after the slowdown: beyond ball A, on the neck's axis.
    const glm::vec3 c = r.leak->centre();
    EXPECT_GT(c.x, kBallA.x + kBallRadius - 2.0F) << c.x;
    EXPECT_NEAR(c.y, 16.0F, 4.0F);
    EXPECT_NEAR(c.z, 16.0F, 4.0F);
    // Stopped early in ball B, not after filling it.
    EXPECT_LT(insideBeyondNeck(solver.readMask()), kBallVoxels / 2);
    EXPECT_EQ(std::string(stopReasonName(StopReason::Leak)), "leak");
}

TEST_F(SolverLeakTest, WithoutTheWatchTheFrontFillsBothBalls) {
    const std::vector<float> volume = dumbbell();
    LevelSetSolver solver(volume, kDims);
    solver.setParams(kParams);
    solver.addSphere({kBallA, 3.0F});
    const StepResult r = solver.runUntilConverged(3000);
    EXPECT_EQ(r.stopReason, StopReason::Converged);
    EXPECT_FALSE(r.leak.has_value());
    EXPECT_GT(insideBeyondNeck(solver.readMask()), kBallVoxels * 9 / 10);
}

TEST_F(SolverLeakTest, ABarrierOnTheNeckKeepsTheFrontOutOfTheOtherBall) {
    const std::vector<float> volume = dumbbell();
    LevelSetSolver solver(volume, kDims, watching());
    solver.setParams(kParams);
    solver.addSphere({kBallA, 3.0F});
    solver.addBarrier({{{kNeckMiddleX, 16.0F, 16.0F}, 3.0F}});
    const StepResult r = solver.runUntilConverged(3000);
    EXPECT_EQ(r.stopReason, StopReason::Converged) << stopReasonName(r.stopReason);
    EXPECT_EQ(insideBeyondNeck(solver.readMask()), 0U);
    EXPECT_EQ(solver.stats().barriers, 1);
    // Ball A is still filled.
    const std::vector<std::uint8_t> mask = solver.readMask();
    EXPECT_EQ(mask[voxelIndex(kDims, 16, 16, 16)], 1);
    EXPECT_EQ(mask[voxelIndex(kDims, 16 + 9, 16, 16)], 1);
}

TEST_F(SolverLeakTest, ABarrierPlacedAfterTheLeakCutsTheFrontBackAndHolds) {
    const std::vector<float> volume = dumbbell();
    LevelSetSolver solver(volume, kDims, watching());
    solver.setParams(kParams);
    solver.addSphere({kBallA, 3.0F});
    ASSERT_EQ(solver.runUntilConverged(3000).stopReason, StopReason::Leak);
    // The operator erases what leaked, from the neck's middle on, and closes the neck.
    solver.removeSphere({kBallB, kBallB.x - kNeckMiddleX + 1.0F});
    solver.addBarrier({{{kNeckMiddleX, 16.0F, 16.0F}, 3.0F}});
    const StepResult r = solver.runUntilConverged(3000);
    EXPECT_EQ(r.stopReason, StopReason::Converged) << stopReasonName(r.stopReason);
    EXPECT_EQ(insideBeyondNeck(solver.readMask()), 0U);
}

// A positive correction in tissue the threshold calls outside: a plain seed there recedes, a
// keeping sphere holds its voxels while the front grows on elsewhere, and a blocking sphere
// placed over part of it later wins there (the newest barrier decides).
TEST_F(SolverLeakTest, AKeepingSphereStaysInsideWhereTheScanSaysOutside) {
    const std::vector<float> volume = dumbbell();
    const glm::vec3 outside{36.0F, 16.0F, 6.0F}; // background, between the balls below the neck
    LevelSetSolver plain(volume, kDims);
    plain.setParams(kParams);
    plain.addSphere({kBallA, 3.0F});
    plain.addSphere({outside, 3.0F});
    plain.runUntilConverged(2000);
    EXPECT_EQ(inAt(plain.readMask(), outside), 0) << "a plain seed in the background recedes";

    LevelSetSolver kept(volume, kDims);
    kept.setParams(kParams);
    kept.addSphere({kBallA, 3.0F});
    kept.addBarrier({{outside, 3.0F}, true});
    EXPECT_EQ(inAt(kept.readMask(), outside), 1) << "a keeping sphere is inside at once";
    kept.runUntilConverged(2000);
    const std::vector<std::uint8_t> m = kept.readMask();
    EXPECT_EQ(inAt(m, outside), 1);
    EXPECT_EQ(inAt(m, outside + glm::vec3(2.0F, 0.0F, 0.0F)), 1) << "its whole sphere stays";
    EXPECT_EQ(inAt(m, outside + glm::vec3(0.0F, 0.0F, 5.0F)), 0) << "and the front goes no further";
    EXPECT_EQ(inAt(m, kBallA + glm::vec3(9.0F, 0.0F, 0.0F)), 1) << "the rest grows as before";

    kept.addBarrier({{outside, 1.5F}, false});
    kept.runUntilConverged(500);
    EXPECT_EQ(inAt(kept.readMask(), outside), 0)
        << "the newer, blocking sphere wins where both hold";
    EXPECT_EQ(kept.stats().barriers, 2);
}

// A correction's run moves the surface only within its reach: beyond it the surface stays as it
// was (here a seed the threshold would grow into ball B, and the front that would cross the
// neck), until the reach is lifted.
TEST_F(SolverLeakTest, AReachMovesTheSurfaceOnlyAroundTheCorrection) {
    const std::vector<float> volume = dumbbell();
    LevelSetSolver solver(volume, kDims);
    solver.setParams(kParams);
    solver.addSphere({kBallA, 3.0F});
    solver.addSphere({kBallB, 3.0F});
    solver.setReach(Reach{Sphere{kBallA, kBallRadius + 3.0F}});
    EXPECT_EQ(solver.runUntilConverged(3000).stopReason, StopReason::Converged);
    std::vector<std::uint8_t> m = solver.readMask();
    EXPECT_EQ(inAt(m, kBallA + glm::vec3(9.0F, 0.0F, 0.0F)), 1) << "ball A fills";
    EXPECT_EQ(inAt(m, kBallB + glm::vec3(2.0F, 0.0F, 0.0F)), 1) << "ball B's seed stays";
    EXPECT_EQ(inAt(m, kBallB + glm::vec3(6.0F, 0.0F, 0.0F)), 0) << "and does not grow";
    EXPECT_EQ(inAt(m, {kNeckMiddleX, 16.0F, 16.0F}), 0) << "the front stops at the reach";
    solver.setReach(std::nullopt);
    solver.runUntilConverged(3000);
    m = solver.readMask();
    EXPECT_EQ(inAt(m, kBallB + glm::vec3(6.0F, 0.0F, 0.0F)), 1) << "lifted, ball B fills";
    EXPECT_EQ(inAt(m, {kNeckMiddleX, 16.0F, 16.0F}), 1);
    EXPECT_THROW(solver.setReach(Reach{Sphere{{400.0F, 16.0F, 16.0F}, 3.0F}}),
                 std::invalid_argument);
}

// A run within a plain reach processes only the bricks the reach takes in: ball B's seed, which
// the reach holds as it is, adds no brick to any step (its speed is not evaluated either); a
// receding reach, beyond which the surface may still withdraw, keeps them awake.
TEST_F(SolverLeakTest, ARunWithinAReachProcessesNoBrickBeyondIt) {
    const std::vector<float> volume = dumbbell();
    const auto activeAfterOneStep = [&](bool seedB, bool recede) {
        LevelSetSolver solver(volume, kDims);
        solver.setParams(kParams);
        solver.addSphere({kBallA, 3.0F});
        if (seedB) {
            solver.addSphere({kBallB, 3.0F});
        }
        solver.setReach(Reach{Sphere{kBallA, kBallRadius + 3.0F}, recede});
        solver.step(1);
        return solver.stats().activeBricks;
    };
    const std::uint32_t aAlone = activeAfterOneStep(false, false);
    EXPECT_GT(aAlone, 0U);
    EXPECT_EQ(activeAfterOneStep(true, false), aAlone);
    EXPECT_GT(activeAfterOneStep(true, true), aAlone);
}

// A reach that recedes outside (an erase's run taken back, docs/steering.md): beyond it the
// surface withdraws from what the speed refuses and advances nowhere; the plain reach leaves
// both as they are.
TEST_F(SolverLeakTest, BeyondARecedingReachTheSurfaceOnlyWithdraws) {
    const std::vector<float> volume = dumbbell();
    const glm::vec3 stray{54.0F, 4.0F, 4.0F}; // background, 17 voxels from ball B's centre
    for (const bool recede : {true, false}) {
        LevelSetSolver solver(volume, kDims);
        solver.setParams(kParams);
        solver.addSphere({kBallA, 3.0F});
        solver.addSphere({kBallB, 3.0F});
        solver.addSphere({stray, 2.5F});
        solver.setReach(Reach{Sphere{kBallA, kBallRadius + 3.0F}, recede});
        solver.runUntilConverged(3000);
        const std::vector<std::uint8_t> m = solver.readMask();
        EXPECT_EQ(inAt(m, kBallA + glm::vec3(9.0F, 0.0F, 0.0F)), 1) << "ball A fills";
        EXPECT_EQ(inAt(m, kBallB), 1) << "ball B's seed stays";
        EXPECT_EQ(inAt(m, kBallB + glm::vec3(6.0F, 0.0F, 0.0F)), 0) << "and does not grow";
        EXPECT_EQ(inAt(m, {kNeckMiddleX, 16.0F, 16.0F}), 0) << "the front stops at the reach";
        EXPECT_EQ(inAt(m, stray), recede ? 0 : 1) << (recede ? "withdraws" : "stays");
    }
}

TEST_F(SolverLeakTest, RefusesMoreBarriersThanTheShaderHolds) {
    const std::vector<float> volume(countOf(kDims), 0.0F);
    LevelSetSolver solver(volume, kDims);
    for (std::size_t n = 0; n < kMaxBarriers; ++n) {
        solver.addBarrier({{{10.0F + static_cast<float>(n), 16.0F, 16.0F}, 1.0F}});
    }
    EXPECT_THROW(solver.addBarrier({{{40.0F, 16.0F, 16.0F}, 1.0F}}), std::invalid_argument);
    EXPECT_THROW(solver.addBarrier({{{400.0F, 16.0F, 16.0F}, 1.0F}}), std::invalid_argument);
    solver.clearBarriers();
    EXPECT_TRUE(solver.barriers().empty());
}

// A correction paints its sphere and then holds it: held without a second paint, the run that
// follows is the one after addBarrier's own paint, voxel for voxel, for both kinds.
TEST_F(SolverLeakTest, HoldingAPaintedSphereIsAddingItsBarrier) {
    const std::vector<float> volume = dumbbell();
    const glm::vec3 outside{36.0F, 16.0F, 6.0F};
    for (const bool keep : {true, false}) {
        SCOPED_TRACE(keep);
        const Barrier barrier{{keep ? outside : glm::vec3(kNeckMiddleX, 16.0F, 16.0F), 3.0F}, keep};
        std::vector<std::vector<float>> phis;
        for (const bool held : {false, true}) {
            LevelSetSolver solver(volume, kDims);
            solver.setParams(kParams);
            solver.addSphere({kBallA, 3.0F});
            solver.step(40);
            if (keep) {
                solver.addSphere(barrier.sphere);
            } else {
                solver.removeSphere(barrier.sphere);
            }
            if (held) {
                solver.holdBarrier(barrier);
            } else {
                solver.addBarrier(barrier);
            }
            EXPECT_EQ(solver.barriers().size(), 1U);
            solver.step(60);
            phis.push_back(solver.readPhi());
        }
        EXPECT_EQ(phis[0], phis[1]);
    }
}

} // namespace
} // namespace steerseg::test
