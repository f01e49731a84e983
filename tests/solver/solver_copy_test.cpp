// Undo's copies of the level set (solver::LevelSetCopy): a restored copy is the phi it copied,
// bit for bit, across pool growth and edits, and the pool it leaves steps on as the original
// did; a copy reads back as a mask; the inside count needs no dense read-back.
#include "solver/level_set_solver.hpp"
#include "support/gpu_fixture.hpp"
#include "support/solver_test_support.hpp"

#include <gtest/gtest.h>
#include <stdexcept>

namespace steerseg::test {
using namespace steerseg::solver; // the solver under test
using namespace steerseg::model;
namespace {

class SolverCopyTest : public GpuTest {};

// No axis a multiple of the brick; the ball reaches the low-x face, so border bricks hold it.
const glm::ivec3 kDims{45, 37, 29};
const LevelSetParams kParams{100.0F, 40.0F, 0.8F};

std::vector<float> ball() {
    return ballVolume(kDims, 0.0F, 100.0F, {4.0F, 18.0F, 14.0F}, 13.0F);
}

TEST_F(SolverCopyTest, ARestoredCopyIsThePhiItCopiedAndStepsOnAsTheOriginalDid) {
    const auto volume = ball();
    SolverOptions options;
    options.sleep = false; // every brick steps: the two runs below see the same bricks
    LevelSetSolver solver(volume, kDims, options);
    solver.addSphere({{8.0F, 18.0F, 14.0F}, 3.0F});
    solver.setParams(kParams);
    solver.step(12);
    const LevelSetCopy copy = solver.copyLevelSet();
    const std::uint32_t capacity = solver.stats().capacity;
    EXPECT_GT(copy.bytes(), capacity * 512 * sizeof(float)); // every slot's phi, and the tables
    const std::vector<float> copied = solver.readPhi();
    const std::vector<std::uint8_t> copiedMask = solver.readMask();
    EXPECT_EQ(solver.readMask(copy), copiedMask);
    solver.step(20);
    const std::vector<float> twentyOn = solver.readPhi();

    // The pool grows with the front and an eraser cuts it: the copy must not follow.
    solver.step(60);
    solver.removeSphere({{8.0F, 18.0F, 14.0F}, 5.0F});
    EXPECT_NE(solver.stats().capacity, capacity);
    ASSERT_NE(solver.readPhi(), copied);

    solver.restoreLevelSet(copy);
    EXPECT_EQ(solver.readPhi(), copied);
    EXPECT_EQ(solver.stats().capacity, capacity);
    EXPECT_EQ(solver.readMask(copy), copiedMask); // restoring keeps the copy
    // Its slot tables are the pool's again: the front goes on as it went from there.
    EXPECT_EQ(solver.step(20).iterations, 20);
    EXPECT_EQ(solver.readPhi(), twentyOn);
    solver.restoreLevelSet(copy);
    EXPECT_EQ(solver.readPhi(), copied);
}

TEST_F(SolverCopyTest, RefusesACopyOfAnotherGridOrNone) {
    const auto volume = ball();
    LevelSetSolver solver(volume, kDims);
    const glm::ivec3 other{16, 16, 16};
    LevelSetSolver small(std::vector<float>(countOf(other), 0.0F), other);
    const LevelSetCopy foreign = small.copyLevelSet();
    EXPECT_THROW(solver.restoreLevelSet(foreign), std::invalid_argument);
    EXPECT_THROW(solver.restoreLevelSet(LevelSetCopy{}), std::invalid_argument);
    EXPECT_THROW((void)solver.readMask(foreign), std::invalid_argument);
    EXPECT_EQ(LevelSetCopy{}.bytes(), 0U);
}

TEST_F(SolverCopyTest, CountsTheInsideVoxelsAsTheMaskDoesBorderBricksIncluded) {
    const auto volume = ball();
    for (const int brickSize : {4, 8, 16}) {
        SCOPED_TRACE(brickSize);
        SolverOptions options;
        options.brickSize = brickSize;
        LevelSetSolver solver(volume, kDims, options);
        EXPECT_EQ(solver.countInside(), 0U);
        solver.addSphere({{4.0F, 18.0F, 14.0F}, 9.0F}); // cut by the low-x face
        solver.setParams(kParams);
        solver.step(30);
        const std::size_t inside = insideCount(solver.readMask());
        EXPECT_GT(inside, 1000U);
        EXPECT_EQ(solver.countInside(), inside);
    }
}

TEST_F(SolverCopyTest, TheInsideCountFollowsStepsAndSphereEditsWithoutACount) {
    // netGained counts what the steps and the edits moved across the surface: the count before
    // plus it is the count after, border bricks (the low-x face, the far corner) included.
    const auto volume = ball();
    LevelSetSolver solver(volume, kDims);
    solver.setParams(kParams);
    solver.addSphere({{4.0F, 18.0F, 14.0F}, 6.0F});
    const auto before = static_cast<std::int64_t>(solver.countInside());
    const std::int64_t net = solver.stats().netGained;
    solver.step(25);
    // A second part, away from the ball, wide enough to cover whole bricks (a brick switches
    // inside at once, without a slot), then a cut that takes whole bricks out the same way.
    solver.addSphere({{30.0F, 20.0F, 14.0F}, 14.0F});
    solver.removeSphere({{28.0F, 20.0F, 12.0F}, 12.0F});
    solver.removeSphere({{4.0F, 18.0F, 14.0F}, 4.0F});
    solver.addSphere({{44.0F, 36.0F, 28.0F}, 3.0F}); // in the far corner's partial bricks
    solver.step(7);                                  // fewer than a check's iterations
    solver.removeSphere({{36.0F, 20.0F, 14.0F}, 2.5F});
    const auto after = static_cast<std::int64_t>(solver.countInside());
    EXPECT_NE(after, before);
    EXPECT_EQ(after - before, solver.stats().netGained - net);
    EXPECT_EQ(after, static_cast<std::int64_t>(insideCount(solver.readMask())));
}

} // namespace
} // namespace steerseg::test
