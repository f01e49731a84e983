// The classifier speed's training voxels from the operator's example spheres.
#include "speed/example_voxels.hpp"

#include <algorithm>
#include <cmath>
#include <gtest/gtest.h>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

namespace steerseg::test {
using speed::Example;
using speed::ExampleVoxels;
using speed::exampleVoxels;
namespace {

constexpr glm::ivec3 kDims{20, 16, 12};

// Voxels of a radius-2 sphere centred on a voxel: 1 + 6 + 12 + 8 + 6 (|d|^2 = 0,1,2,3,4).
constexpr std::size_t kRadius2Ball = 33;

TEST(SpeedExampleVoxels, CountsEachVoxelOnce) {
    const std::vector<Example> one{{glm::vec3(10.0F, 8.0F, 6.0F), 2.0F}};
    EXPECT_EQ(exampleVoxels(one, kDims, 1000, 1, "inside").covered, kRadius2Ball);
    // The same sphere twice, and a copy shifted by one voxel, overlapping.
    const std::vector<Example> overlap{one[0], one[0], {glm::vec3(11.0F, 8.0F, 6.0F), 2.0F}};
    const ExampleVoxels got = exampleVoxels(overlap, kDims, 1000, 1, "inside");
    EXPECT_EQ(got.voxels.size(), got.covered);
    std::vector<glm::ivec3> unique = got.voxels;
    unique.erase(std::unique(unique.begin(), unique.end()), unique.end());
    EXPECT_EQ(unique.size(), got.voxels.size());
    EXPECT_GT(got.covered, kRadius2Ball);
    EXPECT_LT(got.covered, 2 * kRadius2Ball);
}

TEST(SpeedExampleVoxels, OnThickSlicesASphereIsRoundInMillimetres) {
    // Slices twice as thick as the pixels are wide: radius 2 spans 2 pixels and 1 slice, so
    // the ball is the radius-2 disc (13 voxels) and, above and below, the radius-0 point.
    const std::vector<Example> one{{glm::vec3(10.0F, 8.0F, 6.0F), 2.0F}};
    const ExampleVoxels got =
        exampleVoxels(one, kDims, 1000, 1, "inside", glm::vec3(1.0F, 1.0F, 2.0F));
    EXPECT_EQ(got.covered, 13U + 2U);
    for (const glm::ivec3 v : got.voxels) {
        EXPECT_LE(std::abs(v.z - 6), 1);
    }
}

TEST(SpeedExampleVoxels, ClipsToTheScan) {
    // Centred on the corner voxel: one octant of the ball, planes included.
    const std::vector<Example> corner{{glm::vec3(0.0F), 2.0F}};
    const ExampleVoxels got = exampleVoxels(corner, kDims, 1000, 1, "outside");
    EXPECT_EQ(got.covered, 1U + 3U + 3U + 1U + 3U); // |d|^2 = 0, 1, 2, 3, 4 with d >= 0
    for (const glm::ivec3 v : got.voxels) {
        EXPECT_TRUE(glm::all(glm::greaterThanEqual(v, glm::ivec3(0))));
    }
    // A huge radius covers the whole scan and no more.
    const std::vector<Example> huge{{glm::vec3(5.0F), 1e30F}};
    EXPECT_EQ(exampleVoxels(huge, kDims, 10, 1, "outside").covered, 20U * 16U * 12U);
}

TEST(SpeedExampleVoxels, CapsDeterministically) {
    const std::vector<Example> big{{glm::vec3(10.0F, 8.0F, 6.0F), 6.0F}};
    const ExampleVoxels a = exampleVoxels(big, kDims, 100, 4, "inside");
    const ExampleVoxels b = exampleVoxels(big, kDims, 100, 4, "inside");
    const ExampleVoxels c = exampleVoxels(big, kDims, 100, 5, "inside");
    EXPECT_EQ(a.voxels.size(), 100U);
    EXPECT_GT(a.covered, 500U);
    EXPECT_EQ(a.voxels, b.voxels);
    EXPECT_NE(a.voxels, c.voxels);
    // Spread over the sphere, not its first rows.
    const auto [lo, hi] = std::minmax_element(a.voxels.begin(), a.voxels.end(),
                                              [](glm::ivec3 p, glm::ivec3 q) { return p.z < q.z; });
    EXPECT_LE(lo->z, 3);
    EXPECT_GE(hi->z, 9);
}

std::string message(const std::vector<Example>& examples) {
    try {
        (void)exampleVoxels(examples, kDims, 100, 1, "inside");
    } catch (const std::invalid_argument& e) {
        return e.what();
    }
    return "accepted";
}

// A painted stroke's dabs: thousands of overlapping spheres along a path, partly beside the
// scan. Every voxel of their union counts once, and the sample spreads over the whole path.
TEST(SpeedExampleVoxels, ManyOverlappingDabsOfAStroke) {
    constexpr glm::ivec3 big{64, 48, 8};
    std::vector<Example> dabs;
    for (int d = 0; d < 3000; ++d) {
        const float t = static_cast<float>(d) / 3000.0F;
        dabs.push_back(
            {glm::vec3(-4.0F + 72.0F * t, 24.0F + 20.0F * std::sin(6.0F * t), 4.0F), 2.0F});
    }
    std::size_t union_ = 0;
    for (int k = 0; k < big.z; ++k) {
        for (int j = 0; j < big.y; ++j) {
            for (int i = 0; i < big.x; ++i) {
                const glm::vec3 v(static_cast<float>(i), static_cast<float>(j),
                                  static_cast<float>(k));
                union_ += std::any_of(dabs.begin(), dabs.end(), [&](const Example& e) {
                    const glm::dvec3 d = glm::dvec3(v) - glm::dvec3(e.centre);
                    return glm::dot(d, d) <= 4.0;
                });
            }
        }
    }
    const ExampleVoxels got = exampleVoxels(dabs, big, 400, 7, "inside");
    EXPECT_EQ(got.covered, union_);
    EXPECT_EQ(got.voxels.size(), 400U);
    std::vector<glm::ivec3> unique = got.voxels;
    unique.erase(std::unique(unique.begin(), unique.end()), unique.end());
    EXPECT_EQ(unique.size(), got.voxels.size());
    const auto [lo, hi] = std::minmax_element(got.voxels.begin(), got.voxels.end(),
                                              [](glm::ivec3 a, glm::ivec3 b) { return a.x < b.x; });
    EXPECT_LT(lo->x, 6) << "the stroke's start is sampled";
    EXPECT_GT(hi->x, 57) << "and its end";
}

TEST(SpeedExampleVoxels, RefusesBadExamples) {
    EXPECT_EQ(message({}), "classifier speed: no inside examples");
    EXPECT_EQ(message({{glm::vec3(-10.0F), 3.0F}}),
              "classifier speed: the inside examples cover no voxel of the scan (20x16x12)");
    EXPECT_EQ(message({{glm::vec3(5.5F, 5.5F, 5.5F), 0.1F}}),
              "classifier speed: the inside examples cover no voxel of the scan (20x16x12)");
    const float nan = std::numeric_limits<float>::quiet_NaN();
    EXPECT_NE(message({{glm::vec3(nan, 1.0F, 1.0F), 3.0F}}).find("not a finite"),
              std::string::npos);
    EXPECT_NE(message({{glm::vec3(1.0F), -1.0F}}).find("not a finite"), std::string::npos);
    EXPECT_NE(
        message({{glm::vec3(1.0F), std::numeric_limits<float>::infinity()}}).find("not a finite"),
        std::string::npos);
    EXPECT_EQ(message({{glm::vec3(1.0F), 0.0F}}), "accepted"); // the voxel at its centre
}

} // namespace
} // namespace steerseg::test
