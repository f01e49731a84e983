// The per-brick passes' work-group size is the device's choice (64 on a GPU, one SIMD vector on
// llvmpipe: solver_programs.cpp); every number the solver computes must be the same whatever it
// is, so that the GPU's size is checked here on llvmpipe, where the product runs another.
#include "solver/level_set_solver.hpp"
#include "solver/solver_programs.hpp"
#include "support/gpu_fixture.hpp"
#include "support/solver_test_support.hpp"

#include <gtest/gtest.h>
#include <stdexcept>
#include <string>

namespace steerseg::test {
using namespace steerseg::solver; // the solver under test
using namespace steerseg::model;
namespace {

class SolverGroupSizeTest : public GpuTest {};

struct GroupRun {
    std::vector<float> phi;
    StepResult last;
    SolverStats stats;
};

// A rippled ball (rippledBallVolume): seeded, stepped with sleeping bricks, then an erase and a
// correction's reach, then run to its stop.
GroupRun run(int groupSize) {
    const glm::ivec3 d(48, 40, 36);
    const std::vector<float> volume = rippledBallVolume(d, glm::vec3(24.0F, 20.0F, 18.0F), 13.0F);
    SolverOptions options;
    options.groupSize = groupSize;
    LevelSetSolver s(volume, d, options);
    s.addSphere({glm::vec3(20.0F, 20.0F, 18.0F), 3.0F});
    s.addSphere({glm::vec3(30.0F, 18.0F, 16.0F), 2.0F});
    s.setParams(rippledBallParams());
    s.step(120);
    s.removeSphere({glm::vec3(24.0F, 30.0F, 18.0F), 4.0F});
    s.setReach(Reach{Sphere{glm::vec3(24.0F, 30.0F, 18.0F), 10.0F}, false});
    s.step(40);
    s.setReach(std::nullopt);
    GroupRun r;
    r.last = s.runUntilConverged(2000);
    r.phi = s.readPhi();
    r.stats = s.stats();
    return r;
}

TEST_F(SolverGroupSizeTest, ThePerBrickGroupSizeChangesNoNumber) {
    const GroupRun gpu = run(64); // a GPU's size
    EXPECT_EQ(gpu.last.stopReason, StopReason::Converged);
    std::size_t inside = 0;
    for (const float v : gpu.phi) {
        inside += v < 0.0F ? 1U : 0U;
    }
    EXPECT_GT(inside, 4000U); // it grew into the ball (~9,200 voxels)
    for (const int size : {8, 1, 27, 512}) {
        const GroupRun other = run(size);
        EXPECT_EQ(other.last.iterations, gpu.last.iterations) << "group size " << size;
        EXPECT_EQ(other.stats.iterations, gpu.stats.iterations) << "group size " << size;
        ASSERT_EQ(other.phi.size(), gpu.phi.size());
        std::size_t differ = 0;
        for (std::size_t n = 0; n < gpu.phi.size(); ++n) {
            differ += other.phi[n] != gpu.phi[n] ? 1U : 0U;
        }
        EXPECT_EQ(differ, 0U) << "group size " << size;
    }
}

TEST(BrickGroupSize, OneSimdVectorOnACpuRasterizerAndSixtyFourOnAGpu) {
    const std::string llvmpipe = "llvmpipe (LLVM 15.0.6, 256 bits)";
    EXPECT_EQ(detail::brickGroupSize(8, 0, llvmpipe), 8);
    EXPECT_EQ(detail::brickGroupSize(8, 0, "llvmpipe (LLVM 15.0.6, 128 bits)"), 4);
    EXPECT_EQ(detail::brickGroupSize(8, 0, "NVIDIA H200/PCIe/SSE2"), 64);
    EXPECT_EQ(detail::brickGroupSize(16, 0, "Mali-G52"), 64);
    EXPECT_EQ(detail::brickGroupSize(4, 0, "llvmpipe (LLVM 15.0.6, 4096 bits)"), 64); // the brick's
    EXPECT_EQ(detail::brickGroupSize(8, 27, llvmpipe), 27);                           // asked for
}

TEST_F(SolverGroupSizeTest, RefusesASizeNoBrickOrDeviceTakes) {
    const glm::ivec3 d(16, 16, 16);
    const std::vector<float> volume(countOf(d), 0.0F);
    for (const int size : {-1, 513, 1 << 20}) {
        SolverOptions options;
        options.groupSize = size;
        EXPECT_THROW(LevelSetSolver(volume, d, options), std::invalid_argument) << size;
    }
    // A brick of 16 takes 4,096; GLES 3.1 promises 128 invocations and llvmpipe offers 1,024.
    SolverOptions options;
    options.brickSize = 16;
    options.groupSize = 4096;
    EXPECT_THROW(LevelSetSolver(volume, d, options), std::invalid_argument);
}

} // namespace
} // namespace steerseg::test
