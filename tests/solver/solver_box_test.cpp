// The operator's box (model::Box, shaders/solver/barrier_speed.glsl): outside it the speed
// blocks, so a front that would fill the whole bright block stops at the box's faces, and
// recedes into a box that shrank; without a box it fills the block again.
#include "gpu/scan_texture.hpp"
#include "model/box.hpp"
#include "solver/level_set_solver.hpp"
#include "support/gpu_fixture.hpp"
#include "support/solver_test_support.hpp"

#include <gtest/gtest.h>

namespace steerseg::test {
using namespace steerseg::solver; // the solver under test
using namespace steerseg::model;
namespace {

class SolverBoxTest : public GpuTest {};

constexpr glm::ivec3 kDims{48, 40, 32};
const LevelSetParams kParams{100.0F, 40.0F, 0.9F};

// A bright block the front fills: (4..43, 4..35, 4..27).
std::vector<float> block() {
    std::vector<float> v(static_cast<std::size_t>(kDims.x * kDims.y * kDims.z), 0.0F);
    for (int k = 4; k < 28; ++k) {
        for (int j = 4; j < 36; ++j) {
            for (int i = 4; i < 44; ++i) {
                v[voxelIndex(kDims, i, j, k)] = 100.0F;
            }
        }
    }
    return v;
}

// Voxels inside the mask, and those of them outside `box`.
std::pair<std::size_t, std::size_t> count(const std::vector<std::uint8_t>& mask, const Box& box) {
    std::size_t inside = 0;
    std::size_t beyond = 0;
    for (int k = 0; k < kDims.z; ++k) {
        for (int j = 0; j < kDims.y; ++j) {
            for (int i = 0; i < kDims.x; ++i) {
                if (mask[voxelIndex(kDims, i, j, k)] != 0) {
                    ++inside;
                    beyond += contains(box, {i, j, k}) ? 0 : 1;
                }
            }
        }
    }
    return {inside, beyond};
}

TEST_F(SolverBoxTest, TheSurfaceStaysInTheBoxAndFollowsItsChanges) {
    LevelSetSolver solver(block(), kDims);
    solver.setParams(kParams);
    const Box box{{10, 10, 8}, {30, 28, 20}};
    solver.setBox(box);
    solver.addSphere({{20.0F, 20.0F, 14.0F}, 3.0F});
    EXPECT_EQ(solver.runUntilConverged(3000).stopReason, StopReason::Converged);
    const auto [inBox, beyondBox] = count(solver.readMask(), box);
    EXPECT_EQ(beyondBox, 0U);
    // Nearly the whole box: its faces' voxels lie where the blocked speed meets the data's.
    const auto boxVoxels = static_cast<std::size_t>(21 * 19 * 13);
    EXPECT_GT(inBox, boxVoxels * 7 / 10) << inBox << " of " << boxVoxels;

    const Box smaller{{14, 14, 10}, {26, 24, 18}};
    solver.setBox(smaller);
    EXPECT_EQ(solver.runUntilConverged(3000).stopReason, StopReason::Converged);
    const auto [inSmaller, beyondSmaller] = count(solver.readMask(), smaller);
    EXPECT_EQ(beyondSmaller, 0U) << "the surface recedes into a box that shrank";
    EXPECT_GT(inSmaller, 0U);

    solver.setBox(std::nullopt);
    EXPECT_EQ(solver.runUntilConverged(3000).stopReason, StopReason::Converged);
    const auto [all, beyond] = count(solver.readMask(), box);
    EXPECT_GT(beyond, 0U) << "without a box the front fills the block";
    EXPECT_GT(all, boxVoxels);
}

// Under classify the data term lies in [-1, 1], and the hold that blocks the box's outside and an
// erase's sphere (5 at alpha 0.5) would set the time step wherever the front rests on them. It
// does not (measure_speed.comp, timeStepRate): the step is the one a data speed of 1 allows, and
// with that step the surface still never leaves the box nor enters the sphere, however long it
// runs on at rest against them.
TEST_F(SolverBoxTest, UnderClassifyTheHoldDoesNotSetTheTimeStep) {
    const std::vector<float> scan = block();
    std::vector<float> factor(scan.size());
    for (std::size_t v = 0; v < scan.size(); ++v) {
        factor[v] = scan[v] > 50.0F ? 0.8F : -1.0F; // the forest's vote: inside the block
    }
    const gpu::ScanTexture factorTexture(factor, kDims);
    LevelSetSolver solver(scan, kDims);
    const LevelSetParams params{100.0F, 40.0F, 0.5F};
    solver.setParams(params);
    solver.setSpeedInputs({SpeedKind::Classify, 0, factorTexture.exact(), {}, false});
    const Box box{{10, 10, 8}, {30, 28, 20}};
    solver.setBox(box);
    const Sphere erase{{30.0F, 19.0F, 14.0F}, 5.0F};
    solver.addSphere({{18.0F, 19.0F, 14.0F}, 5.0F});
    solver.addBarrier({erase, false});
    EXPECT_EQ(solver.runUntilConverged(3000).stopReason, StopReason::Converged);
    const float before = solver.stats().evolvedTime;
    const int rest = 400;
    EXPECT_EQ(solver.step(rest).iterations, rest);
    const float dt = (solver.stats().evolvedTime - before) / static_cast<float>(rest);
    const float dataOnly = stableTimeStep(timeStepRule(params), params.alpha * 1.0F);
    EXPECT_NEAR(dt, dataOnly, 1e-5F * dataOnly)
        << "the hold's step would be " << stableTimeStep(timeStepRule(params), 2.5F);

    const std::vector<std::uint8_t> mask = solver.readMask();
    const auto [inBox, beyondBox] = count(mask, box);
    EXPECT_EQ(beyondBox, 0U);
    EXPECT_GT(inBox, static_cast<std::size_t>(21 * 19 * 13) / 2);
    std::size_t inErase = 0;
    for (int k = 0; k < kDims.z; ++k) {
        for (int j = 0; j < kDims.y; ++j) {
            for (int i = 0; i < kDims.x; ++i) {
                const bool in = glm::length(glm::vec3(i, j, k) - erase.centre) <= erase.radius;
                inErase += in && mask[voxelIndex(kDims, i, j, k)] != 0 ? 1 : 0;
            }
        }
    }
    EXPECT_EQ(inErase, 0U) << "the surface entered the erase's sphere";
}

TEST_F(SolverBoxTest, RefusesABoxThatDoesNotFit) {
    LevelSetSolver solver(block(), kDims);
    EXPECT_THROW(solver.setBox(Box{{10, 10, 8}, {9, 28, 20}}), std::invalid_argument);
    EXPECT_THROW(solver.setBox(Box{{10, 10, 8}, {30, 28, 32}}), std::invalid_argument);
    EXPECT_FALSE(solver.box().has_value());
}

} // namespace
} // namespace steerseg::test
