// The CPU reference solver (the GPU solver's oracle) against closed-form motions, and the shared
// parameter checks.
#include "model/level_set_params.hpp"
#include "solver/phi_init.hpp"
#include "solver/phi_stencil.hpp"
#include "solver/reference_solver.hpp"

#include <cmath>
#include <gtest/gtest.h>
#include <numbers>
#include <stdexcept>
#include <vector>

namespace steerseg::test {
using namespace steerseg::solver; // the solver under test
using namespace steerseg::model;
namespace {

double equivalentRadius(const std::vector<std::uint8_t>& mask) {
    std::size_t n = 0;
    for (std::uint8_t m : mask) {
        n += m;
    }
    return std::cbrt(3.0 * static_cast<double>(n) / (4.0 * std::numbers::pi));
}

// Classify within the window, on the CPU twin: min(c, window / eps), and finite with eps = 0
// (the window then admits T alone).
TEST(ReferenceSolver, ClassifyWithinTheWindowIsTheSmallerOfBoth) {
    const model::LevelSetParams p{100.0F, 20.0F, 0.5F};
    EXPECT_FLOAT_EQ(dataSpeed(100.0F, 0.3F, model::SpeedKind::Classify, p, true), 0.3F);
    EXPECT_FLOAT_EQ(dataSpeed(110.0F, 0.9F, model::SpeedKind::Classify, p, true), 0.5F);
    EXPECT_FLOAT_EQ(dataSpeed(-900.0F, 0.9F, model::SpeedKind::Classify, p, true), -1.0F);
    EXPECT_FLOAT_EQ(dataSpeed(-900.0F, 0.9F, model::SpeedKind::Classify, p, false), 0.9F);
    const model::LevelSetParams zero{100.0F, 0.0F, 0.5F};
    EXPECT_FLOAT_EQ(dataSpeed(100.0F, 0.9F, model::SpeedKind::Classify, zero, true), 0.0F);
    EXPECT_FLOAT_EQ(dataSpeed(101.0F, 0.9F, model::SpeedKind::Classify, zero, true), -1.0F);
}

TEST(ReferenceSolver, CurvatureFlowShrinksSphereAsRSquaredMinus4t) {
    const glm::ivec3 d{36, 36, 36};
    ReferenceSolver s(std::vector<float>(36 * 36 * 36, 0.0F), d);
    s.addSphere({{18, 18, 18}, 11.0F});
    s.setParams({0.0F, 0.0F, 0.0F}); // alpha = 0: pure mean-curvature flow
    for (const float t : {5.0F, 15.0F, 25.0F}) {
        s.step(100000, t);
        EXPECT_FLOAT_EQ(s.evolvedTime(), t);
        EXPECT_NEAR(equivalentRadius(s.mask()), std::sqrt(121.0 - 4.0 * static_cast<double>(t)),
                    0.3)
            << "t=" << static_cast<double>(t);
    }
}

TEST(ReferenceSolver, DataTermGrowsSphereAtSpeedEps) {
    const glm::ivec3 d{40, 40, 40};
    ReferenceSolver s(std::vector<float>(40 * 40 * 40, 100.0F), d);
    s.addSphere({{20, 20, 20}, 5.0F});
    s.setParams({100.0F, 2.0F, 1.0F}); // D = eps - |I - T| = 2 voxels per unit time
    s.step(100000, 5.0F);
    EXPECT_NEAR(equivalentRadius(s.mask()), 15.0, 0.6);
}

TEST(ReferenceSolver, MaskToPhiPutsZeroHalfwayAndClamps) {
    const glm::ivec3 d{10, 4, 4};
    std::vector<std::uint8_t> mask(160, 0);
    for (int k = 0; k < 4; ++k) {
        for (int j = 0; j < 4; ++j) {
            for (int i = 0; i < 5; ++i) {
                mask[static_cast<std::size_t>(i + 10 * (j + 4 * k))] = 1;
            }
        }
    }
    const std::vector<float> phi = maskToPhi(mask, d);
    EXPECT_FLOAT_EQ(phi[4], -0.5F);
    EXPECT_FLOAT_EQ(phi[5], 0.5F);
    EXPECT_FLOAT_EQ(phi[7], 2.5F);
    EXPECT_FLOAT_EQ(phi[0], -4.0F); // 4.5 clamped to kPhiFar
    EXPECT_EQ(insideMask(phi), mask);
}

TEST(LevelSetParams, RejectsBadValuesWithClearMessages) {
    auto message = [](const LevelSetParams& p) {
        try {
            validateParams(p);
        } catch (const std::invalid_argument& e) {
            return std::string(e.what());
        }
        return std::string("accepted");
    };
    EXPECT_NE(message({0.0F, -1.0F, 0.5F}).find("eps must be >= 0"), std::string::npos);
    EXPECT_NE(message({0.0F, 1.0F, 1.5F}).find("alpha must be in [0, 1]"), std::string::npos);
    EXPECT_NE(message({0.0F, 1.0F, -0.1F}).find("alpha"), std::string::npos);
    EXPECT_NE(message({NAN, 1.0F, 0.5F}).find("finite"), std::string::npos);
    EXPECT_EQ(message({100.0F, 0.0F, 0.0F}), "accepted");
}

TEST(LevelSetParams, ASphereCountsItsRadiusAlongTheFinestAxis) {
    EXPECT_EQ(sphereScale({0.5, 0.5, 2.0}), glm::vec3(1.0F, 1.0F, 4.0F));
    EXPECT_EQ(sphereScale({1.0, 1.0, 1.0}), glm::vec3(1.0F));
    EXPECT_EQ(sphereScale({1.0, 0.0, 1.0}), glm::vec3(1.0F)); // no spacing: voxel steps
    EXPECT_EQ(sphereScale({1.0, std::nan(""), 1.0}), glm::vec3(1.0F));
    const Sphere s{{10.0F, 10.0F, 10.0F}, 4.0F};
    // Isotropic: the Euclidean distance, exactly.
    EXPECT_FLOAT_EQ(sphereDistance(s, {13.0F, 14.0F, 10.0F}), 1.0F);
    EXPECT_FLOAT_EQ(sphereDistance(s, {10.0F, 10.0F, 10.0F}), -4.0F);
    // Slices 4 pixels thick: the surface is 1 slice above the centre and 4 pixels beside it,
    // and the distance is in voxel steps.
    const glm::vec3 thick(1.0F, 1.0F, 4.0F);
    EXPECT_FLOAT_EQ(sphereDistance(s, {10.0F, 10.0F, 11.0F}, thick), 0.0F);
    EXPECT_FLOAT_EQ(sphereDistance(s, {10.0F, 10.0F, 12.0F}, thick), 1.0F);
    EXPECT_FLOAT_EQ(sphereDistance(s, {16.0F, 10.0F, 10.0F}, thick), 2.0F);
    EXPECT_FLOAT_EQ(sphereDistance(s, {10.0F, 10.0F, 10.0F}, thick), -1.0F);
    EXPECT_FLOAT_EQ(sphereHalfExtent(s, thick).z, 1.0F);
    EXPECT_TRUE(sphereHolds(s, {14.0, 10.0, 10.0}, thick));
    EXPECT_TRUE(sphereHolds(s, {10.0, 10.0, 11.0}, thick));
    EXPECT_FALSE(sphereHolds(s, {11.0, 10.0, 11.0}, thick));
    const VoxelBox box = sphereVoxelBox(s, thick, {12, 30, 30});
    EXPECT_EQ(box.lo, glm::ivec3(6, 6, 9));
    EXPECT_EQ(box.hi, glm::ivec3(11, 14, 11)) << "clipped to the grid";
}

TEST(LevelSetParams, RejectsSpheresOutsideTheVolume) {
    const glm::ivec3 d{10, 10, 10};
    EXPECT_THROW(validateSphere({{10, 5, 5}, 2.0F}, d), std::invalid_argument);
    EXPECT_THROW(validateSphere({{-1, 5, 5}, 2.0F}, d), std::invalid_argument);
    EXPECT_THROW(validateSphere({{5, 5, 5}, 0.0F}, d), std::invalid_argument);
    EXPECT_THROW(validateSphere({{5, 5, 5}, INFINITY}, d), std::invalid_argument);
    EXPECT_NO_THROW(validateSphere({{9, 0, 5}, 2.0F}, d));
    ReferenceSolver s(std::vector<float>(1000, 0.0F), d);
    EXPECT_THROW(s.addSphere({{5, 5, 50}, 2.0F}), std::invalid_argument);
    EXPECT_THROW(s.removeSphere({{5, 5, 5}, 3e9F}), std::invalid_argument);
    EXPECT_THROW(s.setParams({0.0F, -2.0F, 0.5F}), std::invalid_argument);
    EXPECT_THROW(s.step(1), std::logic_error); // no parameters yet
}

// The radius is bounded by the volume's diagonal (17.3 voxels here): a larger one changes
// nothing but overflows the edit's integer bounds.
TEST(LevelSetParams, RejectsRadiiThatDoNotFitTheVolume) {
    const glm::ivec3 d{10, 10, 10};
    const auto message = [&](const Sphere& s) {
        try {
            validateSphere(s, d);
        } catch (const std::invalid_argument& e) {
            return std::string(e.what());
        }
        return std::string("accepted");
    };
    EXPECT_EQ(message({{5, 5, 5}, 3e9F}),
              "sphere radius 3e+09 voxels is larger than the volume's diagonal (17.3205 voxels "
              "for 10 x 10 x 10)");
    EXPECT_NE(message({{5, 5, 5}, -2.0F}).find("positive"), std::string::npos);
    EXPECT_NE(message({{5, 5, 5}, NAN}).find("positive"), std::string::npos);
    EXPECT_NE(message({{NAN, 5, 5}, 2.0F}).find("lies outside the volume"), std::string::npos);
    EXPECT_NE(message({{5, -INFINITY, 5}, 2.0F}).find("lies outside"), std::string::npos);
    EXPECT_NE(message({{5, 5, 3e9F}, 2.0F}).find("lies outside"), std::string::npos);
    EXPECT_EQ(message({{5, 5, 5}, 17.3F}), "accepted");
}

TEST(ReferenceSolver, RejectsEmptyThresholdRange) {
    ReferenceSolver s(std::vector<float>(27, 0.0F), {3, 3, 3});
    EXPECT_THROW(s.initFromThreshold(5.0F, 1.0F), std::invalid_argument);
}

} // namespace
} // namespace steerseg::test
