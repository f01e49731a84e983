// Outside examples from the tissue that stopped an accepted surface (speed::outsideShell).
#include "speed/surface_shell.hpp"

#include <cmath>
#include <gtest/gtest.h>
#include <limits>
#include <stdexcept>
#include <vector>

namespace steerseg::test {
using speed::LocalWindow;
using speed::outsideShell;
using speed::ShellParams;
namespace {

constexpr glm::ivec3 kDims{24, 24, 24};
const glm::vec3 kCentre(12.0F);
constexpr float kBall = 6.0F; // the surface: a ball of this radius

float distance(int i, int j, int k) {
    return glm::length(
        glm::vec3(static_cast<float>(i), static_cast<float>(j), static_cast<float>(k)) - kCentre);
}

// A ball of tissue 100 whose right half (i > 12) goes on to radius 9 (the front stopped there
// for another reason than the tissue), in a background of 0; phi the ball's distance.
struct Scene {
    Volume scan{VoxelType::Float32, Geometry{kDims}};
    std::vector<float> phi;
    Scene() {
        std::span<float> v = scan.voxels<float>();
        phi.resize(v.size());
        for (int k = 0; k < kDims.z; ++k) {
            for (int j = 0; j < kDims.y; ++j) {
                for (int i = 0; i < kDims.x; ++i) {
                    const float d = distance(i, j, k);
                    const std::size_t at = linearIndex(kDims, i, j, k);
                    phi[at] = d - kBall;
                    v[at] = d <= kBall || (i > 12 && d <= 9.0F) ? 100.0F : 0.0F;
                }
            }
        }
    }
};

ShellParams window(std::size_t most) {
    ShellParams p;
    p.low = 90.0F;
    p.high = 110.0F;
    p.most = most;
    return p;
}

std::size_t shellVoxels(int iMax) {
    std::size_t n = 0;
    for (int k = 0; k < kDims.z; ++k) {
        for (int j = 0; j < kDims.y; ++j) {
            for (int i = 0; i <= iMax; ++i) {
                const float p = distance(i, j, k) - kBall;
                n += p > 1.0F && p <= 3.0F ? 1 : 0;
            }
        }
    }
    return n;
}

TEST(SpeedSurfaceShell, TakesTheTissueJustOutsideThatTheWindowRefuses) {
    const Scene s;
    const std::vector<model::Sphere> got = outsideShell(s.phi, s.scan, window(100000));
    ASSERT_FALSE(got.empty());
    for (const model::Sphere& e : got) {
        const glm::ivec3 v(e.centre);
        const float d = distance(v.x, v.y, v.z);
        EXPECT_GT(d - kBall, 1.0F);
        EXPECT_LE(d - kBall, 3.0F);
        EXPECT_FALSE(v.x > 12) << "the window takes the tissue there in: it did not stop the front";
        EXPECT_FLOAT_EQ(e.radius, 1.0F);
    }
    // All of them: the left half of the shell, i <= 12.
    EXPECT_EQ(got.size(), shellVoxels(12));
}

TEST(SpeedSurfaceShell, AtMostTheCapSpreadOverTheShellAndTheSameEachTime) {
    const Scene s;
    const std::vector<model::Sphere> got = outsideShell(s.phi, s.scan, window(10));
    ASSERT_EQ(got.size(), 10U);
    // Evenly spaced in raster order: from the lowest slices of the shell to the highest.
    EXPECT_LT(got.front().centre.z, kCentre.z - 4.0F);
    EXPECT_GT(got.back().centre.z, kCentre.z + 4.0F);
    EXPECT_EQ(outsideShell(s.phi, s.scan, window(10)), got);
    EXPECT_TRUE(outsideShell(s.phi, s.scan, window(0)).empty());
}

// Near a correction with a tissue level the front ran with a wider window: what that window
// takes in did not stop it either, within its reach only.
TEST(SpeedSurfaceShell, ALocalWindowAdmitsWhatItReaches) {
    const Scene s;
    const LocalWindow wider{kCentre - glm::vec3(8.0F, 0.0F, 0.0F), 4.0F, -10.0F, 110.0F};
    ShellParams p = window(100000);
    p.local = {&wider, 1};
    const std::vector<model::Sphere> got = outsideShell(s.phi, s.scan, p);
    ASSERT_FALSE(got.empty());
    for (const model::Sphere& e : got) {
        EXPECT_GT(glm::length(e.centre - wider.centre), wider.reach);
    }
    EXPECT_LT(got.size(), outsideShell(s.phi, s.scan, window(100000)).size());
}

TEST(SpeedSurfaceShell, NothingWithoutASurface) {
    const Scene s;
    const std::vector<float> allInside(s.phi.size(), -5.0F);
    EXPECT_TRUE(outsideShell(allInside, s.scan, window(100)).empty());
}

TEST(SpeedSurfaceShell, RefusesWhatItCannotUse) {
    const Scene s;
    const std::vector<float> small(10, 0.0F);
    EXPECT_THROW((void)outsideShell(small, s.scan, window(10)), std::invalid_argument);
    const float nan = std::numeric_limits<float>::quiet_NaN();
    std::vector<ShellParams> bad(5, window(10));
    bad[0].nearVoxels = bad[0].farVoxels;
    bad[1].low = nan;
    bad[2].low = 200.0F; // above high
    bad[3].radius = 0.0F;
    const LocalWindow notFinite{glm::vec3(nan), 1.0F, 0.0F, 1.0F};
    bad[4].local = {&notFinite, 1};
    for (const ShellParams& b : bad) {
        EXPECT_THROW((void)outsideShell(s.phi, s.scan, b), std::invalid_argument);
    }
}

} // namespace
} // namespace steerseg::test
