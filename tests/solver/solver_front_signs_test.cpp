// measure_speed finds the front from the sign rows update_phi keeps (shaders/solver/
// front_signs.glsl) and, where a brick or a face neighbour keeps none, from the bricks' phi. The
// front sets each step's time, so the two must agree to the bit: at bricks cut by the volume's
// end (where phiAt repeats the border voxel), across constant neighbours, after edits, a reach,
// a shrink and a wake, at every brick size.
#include "solver/level_set_solver.hpp"
#include "support/gpu_fixture.hpp"
#include "support/solver_test_support.hpp"

#include <gtest/gtest.h>

namespace steerseg::test {
using namespace steerseg::solver; // the solver under test
using namespace steerseg::model;
namespace {

class SolverFrontSignsTest : public GpuTest, public ::testing::WithParamInterface<int> {};

struct SignsRun {
    std::vector<float> phi;
    SolverStats stats;
    bool converged = false;
    std::vector<std::uint32_t> frontVoxels; // after each step
};

// A rippled ball of 1 in 0 that the volume's ends cut (45 x 48 x 26 voxels: bricks cut by the
// end along x and z, a whole number of them along y; along z at both ends), grown from two seeds,
// then a large seed the ball refuses (its retreat shrinks the pool), an erase and a correction's
// reach, then run to its stop.
SignsRun run(int brickSize, bool fromSignRows) {
    const glm::ivec3 d(45, 48, 26);
    const std::vector<float> volume = rippledBallVolume(d, glm::vec3(30.0F, 34.0F, 12.0F), 15.0F);
    SolverOptions options;
    options.brickSize = brickSize;
    options.frontFromSignRows = fromSignRows;
    options.checkInterval = 1; // the front's voxels read after every step
    LevelSetSolver s(volume, d, options);
    s.addSphere({glm::vec3(36.0F, 40.0F, 14.0F), 3.0F});
    s.addSphere({glm::vec3(24.0F, 30.0F, 10.0F), 2.0F});
    s.setParams(rippledBallParams());
    SignsRun r;
    const auto steps = [&](int n) {
        for (int i = 0; i < n && !s.converged(); ++i) {
            s.runUntilConverged(1);
            r.frontVoxels.push_back(s.stats().frontVoxels);
        }
    };
    steps(100);
    s.addSphere({glm::vec3(12.0F, 10.0F, 8.0F), 7.0F}); // outside the ball: it withdraws
    steps(60);
    s.removeSphere({glm::vec3(30.0F, 44.0F, 16.0F), 4.0F});
    s.setReach(Reach{Sphere{glm::vec3(30.0F, 44.0F, 16.0F), 10.0F}, false});
    steps(40);
    s.setReach(std::nullopt);
    steps(2000);
    r.converged = s.converged();
    r.phi = s.readPhi();
    r.stats = s.stats();
    return r;
}

TEST_P(SolverFrontSignsTest, TheFrontFromTheSignRowsIsTheFrontFromPhi) {
    const SignsRun rows = run(GetParam(), true);
    const SignsRun phi = run(GetParam(), false);
    std::size_t inside = 0;
    for (const float v : rows.phi) {
        inside += v < 0.0F ? 1U : 0U;
    }
    EXPECT_GT(inside, 4000U); // it grew into the ball's part in the volume, to its ends
    EXPECT_GE(rows.stats.poolShrinks, 1);
    EXPECT_TRUE(rows.converged);
    EXPECT_EQ(rows.stats.iterations, phi.stats.iterations);
    EXPECT_EQ(rows.stats.evolvedTime, phi.stats.evolvedTime); // every step's dt, to the bit
    EXPECT_EQ(rows.frontVoxels, phi.frontVoxels);
    ASSERT_EQ(rows.phi.size(), phi.phi.size());
    std::size_t differ = 0;
    for (std::size_t n = 0; n < rows.phi.size(); ++n) {
        differ += rows.phi[n] != phi.phi[n] ? 1U : 0U;
    }
    EXPECT_EQ(differ, 0U);
}

INSTANTIATE_TEST_SUITE_P(BrickSizes, SolverFrontSignsTest, ::testing::Values(4, 8, 16),
                         [](const auto& p) { return "Brick" + std::to_string(p.param); });

} // namespace
} // namespace steerseg::test
