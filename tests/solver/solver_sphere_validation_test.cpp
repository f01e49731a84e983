// LevelSetSolver::addSphere/removeSphere refuse a sphere that does not fit the volume with
// std::invalid_argument (validateSphere), before touching the GPU: the level set is unchanged.
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

} // namespace
} // namespace steerseg::test
