// Brick mechanics of the GPU solver, each checked against the dense CPU reference: surfaces
// across brick corners and the volume border, sizes that are not a multiple of the brick, pool
// growth past the first allocation, steering mid-run, dense mode, threshold/mask start; and the
// storage bound of a band that stopped moving.
#include "solver/level_set_solver.hpp"
#include "solver/phi_init.hpp"
#include "solver/reference_solver.hpp"
#include "support/gpu_fixture.hpp"
#include "support/solver_test_support.hpp"

#include <gtest/gtest.h>

namespace steerseg::test {
using namespace steerseg::solver; // the solver under test
using namespace steerseg::model;
namespace {

class SolverBricksTest : public GpuTest {};

void expectAgree(const glm::ivec3& d, const std::vector<std::uint8_t>& gpu,
                 const std::vector<std::uint8_t>& cpu) {
    ASSERT_EQ(gpu.size(), cpu.size());
    ASSERT_GT(insideCount(cpu), 0U);
    EXPECT_GE(dice(gpu, cpu), 0.99) << "gpu " << insideCount(gpu) << " cpu " << insideCount(cpu);
    EXPECT_EQ(differencesOffSurface(d, gpu, cpu), 0U);
}

// A ball of intensity 100 in 0 that reaches the volume's border on the low-x side.
std::vector<float> borderBall(const glm::ivec3& d) {
    return ballVolume(d, 0.0F, 100.0F, {4.0F, 18.0F, 14.0F}, 13.0F);
}

TEST_F(SolverBricksTest, SurfaceAcrossBrickCornersAndVolumeBorderInOddSizedVolume) {
    const glm::ivec3 d{45, 37, 29}; // no axis a multiple of 4, 8 or 16
    const auto volume = borderBall(d);
    const LevelSetParams params{100.0F, 40.0F, 0.8F};
    const Sphere corner{{16.0F, 16.0F, 16.0F}, 3.0F}; // centred on a brick corner
    const Sphere border{{1.0F, 20.0F, 12.0F}, 4.0F};  // cut by the volume's face
    ReferenceSolver cpu(volume, d);
    for (const Sphere& s : {corner, border}) {
        cpu.addSphere(s);
    }
    cpu.setParams(params);
    cpu.step(40);
    for (const int brickSize : {4, 8, 16}) { // each has its own shell layout (brick_shell.glsl)
        SCOPED_TRACE(brickSize);
        SolverOptions options;
        options.brickSize = brickSize;
        LevelSetSolver gpu(volume, d, options);
        for (const Sphere& s : {corner, border}) {
            gpu.addSphere(s);
        }
        gpu.setParams(params);
        EXPECT_EQ(gpu.step(40).iterations, 40);
        EXPECT_NEAR(gpu.stats().evolvedTime, cpu.evolvedTime(), 1e-3F * cpu.evolvedTime());
        const auto mask = gpu.readMask();
        expectAgree(d, mask, cpu.mask());
        EXPECT_EQ(mask[voxelIndex(d, 0, 20, 12)], 1); // the surface reaches the border
        // The mask read straight from the bricks is the dense phi's sign, at the far faces'
        // cut bricks too, and whole inside bricks are counted.
        EXPECT_EQ(mask, insideMask(gpu.readPhi()));
        EXPECT_EQ(insideCount(mask), gpu.countInside());
    }
}

// phi is stored once (plus each slot's shell scratch) and the pool shrinks to a small margin once
// the band stops growing: storage within 2x the used bricks' phi plus the page table.
TEST_F(SolverBricksTest, StorageOfAStillBandIsWithinTwiceItsBricks) {
    const glm::ivec3 d{64, 64, 64};
    const std::vector<float> volume(countOf(d), 100.0F);
    LevelSetSolver gpu(volume, d);
    gpu.addSphere({{32, 32, 32}, 16.0F}); // the edit reserves slots for its whole box
    gpu.setParams({100.0F, 0.0F, 0.9F});  // D = 0: only a little curvature moves the surface
    gpu.step(48);
    const SolverStats s = gpu.stats();
    ASSERT_GT(s.activeBricks, 50U);
    const std::size_t brickBytes = 8 * 8 * 8 * sizeof(float);
    const std::size_t bound =
        2 * s.activeBricks * brickBytes + s.totalBricks * sizeof(std::uint32_t);
    EXPECT_LE(s.levelSetBytes, bound) << s.capacity << " slots for " << s.activeBricks << " bricks";
    EXPECT_GE(s.poolShrinks, 1);
}

TEST_F(SolverBricksTest, PoolGrowsPastItsFirstAllocation) {
    const glm::ivec3 d{40, 40, 32};
    const std::vector<float> volume(countOf(d), 100.0F);
    const LevelSetParams params{100.0F, 5.0F, 0.9F};
    for (const int checkInterval : {8, 64}) { // 64: the pool runs out between checks and stalls
        SolverOptions options;
        options.checkInterval = checkInterval;
        LevelSetSolver gpu(volume, d, options);
        ReferenceSolver cpu(volume, d);
        gpu.addSphere({{20, 20, 16}, 2.0F});
        cpu.addSphere({{20, 20, 16}, 2.0F});
        const std::uint32_t firstCapacity = gpu.stats().capacity;
        gpu.setParams(params);
        cpu.setParams(params);
        EXPECT_EQ(gpu.step(40).iterations, 40);
        cpu.step(40);
        const SolverStats stats = gpu.stats();
        EXPECT_GT(stats.capacity, firstCapacity);
        EXPECT_GE(stats.poolGrowths, 1);
        std::printf("check every %d: capacity %u -> %u, %d growths, %d stalls\n", checkInterval,
                    firstCapacity, stats.capacity, stats.poolGrowths, stats.stalls);
        expectAgree(d, gpu.readMask(), cpu.mask());
    }
}

TEST_F(SolverBricksTest, SteeringMidRunMatchesReference) {
    const glm::ivec3 d{40, 40, 36};
    const auto volume = ballVolume(d, 0.0F, 100.0F, {20, 20, 18}, 12.0F);
    LevelSetSolver gpu(volume, d);
    ReferenceSolver cpu(volume, d);
    const Sphere seed{{18, 20, 18}, 4.0F};
    gpu.addSphere(seed);
    cpu.addSphere(seed);
    gpu.setParams({100.0F, 50.0F, 1.0F});
    cpu.setParams({100.0F, 50.0F, 1.0F});
    gpu.step(12);
    cpu.step(12);
    // Between two iterations: new parameters, a second seed and an eraser.
    const LevelSetParams steered{90.0F, 30.0F, 0.6F};
    const Sphere second{{30, 30, 18}, 3.0F};
    const Sphere eraser{{14, 20, 18}, 3.0F};
    gpu.setParams(steered);
    cpu.setParams(steered);
    gpu.addSphere(second);
    cpu.addSphere(second);
    gpu.removeSphere(eraser);
    cpu.removeSphere(eraser);
    gpu.step(20);
    cpu.step(20);
    expectAgree(d, gpu.readMask(), cpu.mask());
}

// An interactive caller steps a few iterations per frame: the pool is then checked after every
// call and the control block is taken from the previous call, not read back first.
TEST_F(SolverBricksTest, SteppingOneIterationPerCallMatchesOneCall) {
    const glm::ivec3 d{40, 36, 32};
    const auto volume = ballVolume(d, 0.0F, 100.0F, {20, 18, 16}, 11.0F);
    LevelSetSolver a(volume, d);
    LevelSetSolver b(volume, d);
    for (LevelSetSolver* s : {&a, &b}) {
        s->addSphere({{20, 18, 16}, 3.0F});
        s->setParams({100.0F, 40.0F, 0.7F});
    }
    EXPECT_EQ(a.step(30).iterations, 30);
    float time = 0.0F;
    for (int n = 0; n < 30; ++n) {
        const StepResult r = b.step(1);
        EXPECT_EQ(r.iterations, 1);
        EXPECT_GT(r.evolvedTime, time);
        time = r.evolvedTime;
    }
    EXPECT_FLOAT_EQ(a.stats().evolvedTime, b.stats().evolvedTime);
    EXPECT_EQ(a.readMask(), b.readMask());
}

TEST_F(SolverBricksTest, DenseModeMatchesSparseMode) {
    const glm::ivec3 d{40, 36, 32};
    const auto volume = ballVolume(d, 0.0F, 100.0F, {20, 18, 16}, 11.0F);
    SolverOptions dense;
    dense.dense = true;
    LevelSetSolver a(volume, d);
    LevelSetSolver b(volume, d, dense);
    for (LevelSetSolver* s : {&a, &b}) {
        s->addSphere({{20, 18, 16}, 4.0F});
        s->setParams({100.0F, 40.0F, 0.7F});
        s->step(24);
    }
    EXPECT_EQ(b.stats().activeBricks, b.stats().totalBricks);
    EXPECT_LT(a.stats().peakActiveBricks, a.stats().totalBricks);
    expectAgree(d, a.readMask(), b.readMask());
}

TEST_F(SolverBricksTest, ThresholdAndMaskStartsMatchReference) {
    const glm::ivec3 d{36, 36, 36};
    const auto volume = ballVolume(d, 0.0F, 100.0F, {18, 18, 18}, 10.0F);
    const LevelSetParams params{100.0F, 20.0F, 0.5F};
    LevelSetSolver gpu(volume, d);
    ReferenceSolver cpu(volume, d);
    gpu.initFromThreshold(volume, 50.0F, 150.0F);
    cpu.initFromThreshold(50.0F, 150.0F);
    EXPECT_EQ(gpu.readMask(), cpu.mask());
    gpu.setParams(params);
    cpu.setParams(params);
    gpu.step(20);
    cpu.step(20);
    expectAgree(d, gpu.readMask(), cpu.mask());

    std::vector<std::uint8_t> box(countOf(d), 0);
    for (int k = 10; k < 26; ++k) {
        for (int j = 12; j < 24; ++j) {
            for (int i = 8; i < 30; ++i) {
                box[voxelIndex(d, i, j, k)] = 1;
            }
        }
    }
    gpu.initFromMask(box);
    cpu.initFromMask(box);
    EXPECT_EQ(gpu.readMask(), box);
    gpu.step(20);
    cpu.step(20);
    expectAgree(d, gpu.readMask(), cpu.mask());
}

TEST_F(SolverBricksTest, RejectsBadInputWithClearErrors) {
    const glm::ivec3 d{16, 16, 16};
    LevelSetSolver s(std::vector<float>(countOf(d), 0.0F), d);
    EXPECT_THROW(s.setParams({0.0F, -1.0F, 0.5F}), std::invalid_argument);
    EXPECT_THROW(s.setParams({0.0F, 1.0F, 2.0F}), std::invalid_argument);
    EXPECT_THROW(s.addSphere({{16, 0, 0}, 2.0F}), std::invalid_argument);
    EXPECT_THROW(s.step(1), std::logic_error); // no parameters
    EXPECT_THROW(LevelSetSolver(std::vector<float>(10, 0.0F), d), std::invalid_argument);
    SolverOptions odd;
    odd.brickSize = 5;
    EXPECT_THROW(LevelSetSolver(std::vector<float>(countOf(d), 0.0F), d, odd),
                 std::invalid_argument);
}

} // namespace
} // namespace steerseg::test
