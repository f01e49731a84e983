// LevelSetSolver::addSphere/removeSphere refuse a sphere that does not fit the volume with
// std::invalid_argument (validateSphere), before touching the GPU: the level set is unchanged.
// On a scan with thick slices a sphere is round in millimetres (model::Sphere).
#include "core/volume.hpp"
#include "solver/level_set_solver.hpp"
#include "support/gpu_fixture.hpp"

#include <cmath>
#include <gtest/gtest.h>
#include <limits>

namespace steerseg::test {
using namespace steerseg::solver; // the solver under test
using namespace steerseg::model;
namespace {

using SolverSphereValidation = GpuTest;

TEST_F(SolverSphereValidation, BadSpheresAreRefusedAndLeaveTheLevelSetAlone) {
    const glm::ivec3 d{16, 16, 16};
    LevelSetSolver s(std::vector<float>(16 * 16 * 16, 0.0F), d);
    s.addSphere({{8.0F, 8.0F, 8.0F}, 3.0F});
    const std::vector<std::uint8_t> before = s.readMask();
    const float nan = std::numeric_limits<float>::quiet_NaN();
    const float inf = std::numeric_limits<float>::infinity();
    const Sphere bad[] = {
        {{8.0F, 8.0F, 8.0F}, 3e9F}, {{8.0F, 8.0F, 8.0F}, -1.0F}, {{8.0F, 8.0F, 8.0F}, nan},
        {{8.0F, 8.0F, 8.0F}, inf},  {{nan, 8.0F, 8.0F}, 2.0F},   {{8.0F, -inf, 8.0F}, 2.0F},
        {{8.0F, 8.0F, 3e9F}, 2.0F}, {{-0.5F, 8.0F, 8.0F}, 2.0F},
    };
    for (const Sphere& b : bad) {
        SCOPED_TRACE(testing::Message() << "centre (" << b.centre.x << ", " << b.centre.y << ", "
                                        << b.centre.z << ") radius " << b.radius);
        EXPECT_THROW(s.addSphere(b), std::invalid_argument);
        EXPECT_THROW(s.removeSphere(b), std::invalid_argument);
    }
    try {
        s.addSphere({{8.0F, 8.0F, 8.0F}, 3e9F});
    } catch (const std::invalid_argument& e) {
        EXPECT_NE(std::string(e.what()).find("larger than the volume's diagonal"),
                  std::string::npos)
            << e.what();
    }
    EXPECT_EQ(s.readMask(), before);
    // The largest radius that fits still works: every voxel inside.
    s.addSphere({{8.0F, 8.0F, 8.0F}, glm::length(glm::vec3(d))});
    const std::vector<std::uint8_t> all = s.readMask();
    EXPECT_EQ(std::count(all.begin(), all.end(), std::uint8_t{1}),
              static_cast<std::ptrdiff_t>(all.size()));
}

TEST_F(SolverSphereValidation, OnThickSlicesASphereIsRoundInMillimetres) {
    Geometry g;
    g.dims = {24, 24, 12};
    g.spacing = {0.8, 0.8, 2.4}; // slices 3 pixels thick
    Volume scan(VoxelType::Float32, g);
    LevelSetSolver s(scan);
    EXPECT_EQ(s.sphereScale(), glm::vec3(1.0F, 1.0F, 3.0F));
    const Sphere seed{{12.0F, 12.0F, 6.0F}, 7.0F};
    const Sphere cut{{16.0F, 12.0F, 6.0F}, 3.0F};
    s.addSphere(seed);
    s.removeSphere(cut);
    const std::vector<std::uint8_t> mask = s.readMask();
    std::size_t inside = 0;
    for (int k = 0; k < g.dims.z; ++k) {
        for (int j = 0; j < g.dims.y; ++j) {
            for (int i = 0; i < g.dims.x; ++i) {
                const glm::vec3 v(i, j, k);
                const bool want = sphereDistance(seed, v, s.sphereScale()) < 0.0F &&
                                  sphereDistance(cut, v, s.sphereScale()) > 0.0F;
                inside += want ? 1 : 0;
                ASSERT_EQ(mask[static_cast<std::size_t>(i + g.dims.x * (j + g.dims.y * k))] != 0,
                          want)
                    << "voxel (" << i << ", " << j << ", " << k << ")";
            }
        }
    }
    // 7 pixels across and 2 slices through (7 / 3 = 2.33): not a ball of 7 slices.
    EXPECT_GT(inside, 300U);
    EXPECT_LT(inside, 700U); // the voxel ball of radius 7 would hold twice as many
    EXPECT_EQ(mask[static_cast<std::size_t>(12 + 24 * (12 + 24 * 8))], 1);
    EXPECT_EQ(mask[static_cast<std::size_t>(12 + 24 * (12 + 24 * 9))], 0);
}

} // namespace
} // namespace steerseg::test
