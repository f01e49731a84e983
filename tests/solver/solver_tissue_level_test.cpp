// A keeping barrier's tissue level (model::TissueLevel, shaders/solver/barrier_speed.glsl): a
// correction put on tissue the window at T misses teaches the threshold that tissue within its
// reach, and nowhere else. The scene: one box of tissue whose near half lies at T and whose far
// half is brighter, as a tumour's enhancing rim or a brain's brighter white matter beside what
// the probe took in, with a layer of partial volume between them. The window at T stops the
// front at the layer.
#include "solver/level_set_solver.hpp"
#include "support/gpu_fixture.hpp"
#include "support/solver_test_support.hpp"

#include <gtest/gtest.h>
#include <limits>

namespace steerseg::test {
using namespace steerseg::solver; // the solver under test
using namespace steerseg::model;
namespace {

class SolverTissueLevelTest : public GpuTest {};

constexpr glm::ivec3 kDims{72, 32, 32};
constexpr int kStep = 36; // the partial-volume layer starts here
constexpr int kLayer = 4; // its thickness
const LevelSetParams kParams{100.0F, 40.0F, 0.9F};
constexpr glm::vec3 kCorrection{46.0F, 16.0F, 16.0F};
constexpr float kReach = 12.0F;

std::vector<float> twoLevelBox() {
    std::vector<float> v(static_cast<std::size_t>(kDims.x * kDims.y * kDims.z), 0.0F);
    for (int k = 8; k < 24; ++k) {
        for (int j = 8; j < 24; ++j) {
            for (int i = 4; i < 68; ++i) {
                v[voxelIndex(kDims, i, j, k)] =
                    i < kStep ? 100.0F : (i < kStep + kLayer ? 150.0F : 200.0F);
            }
        }
    }
    return v;
}

std::uint8_t inAt(const std::vector<std::uint8_t>& mask, int i, int j, int k) {
    return mask[voxelIndex(kDims, i, j, k)];
}

std::vector<std::uint8_t> correctedRun(const std::optional<TissueLevel>& tissue) {
    LevelSetSolver solver(twoLevelBox(), kDims);
    solver.setParams(kParams);
    solver.addSphere({{16.0F, 16.0F, 16.0F}, 3.0F});
    EXPECT_EQ(solver.runUntilConverged(2000).stopReason, StopReason::Converged);
    const std::vector<std::uint8_t> first = solver.readMask();
    EXPECT_TRUE(inAt(first, kStep - 2, 16, 16));
    EXPECT_FALSE(inAt(first, kStep + 2, 16, 16)) << "the window at T stops at the step";
    solver.addBarrier({{kCorrection, 3.0F}, true, tissue});
    EXPECT_EQ(solver.runUntilConverged(2000).stopReason, StopReason::Converged);
    return solver.readMask();
}

TEST_F(SolverTissueLevelTest, TheCorrectionsTissueIsAdmittedWithinItsReachOnly) {
    const std::vector<std::uint8_t> mask = correctedRun(TissueLevel{200.0F, kReach});
    EXPECT_TRUE(inAt(mask, static_cast<int>(kCorrection.x) + 9, 16, 16)) << "within the reach";
    EXPECT_TRUE(inAt(mask, kStep + 1, 12, 12)) << "the layer between T and the level";
    EXPECT_FALSE(inAt(mask, static_cast<int>(kCorrection.x) + 16, 16, 16)) << "beyond the reach";
    EXPECT_FALSE(inAt(mask, static_cast<int>(kCorrection.x), 16, 5))
        << "background within the reach is not the corrected tissue";
}

TEST_F(SolverTissueLevelTest, WithoutALevelOnlyTheSphereKeeps) {
    const std::vector<std::uint8_t> mask = correctedRun(std::nullopt);
    EXPECT_TRUE(inAt(mask, static_cast<int>(kCorrection.x), 16, 16));
    EXPECT_FALSE(inAt(mask, static_cast<int>(kCorrection.x) + 9, 16, 16));
}

TEST_F(SolverTissueLevelTest, RefusesALevelItCannotApply) {
    LevelSetSolver solver(twoLevelBox(), kDims);
    const float nan = std::numeric_limits<float>::quiet_NaN();
    const Sphere s{kCorrection, 3.0F};
    const Barrier bad[] = {
        {s, false, TissueLevel{200.0F, kReach}}, // a blocking sphere admits nothing
        {s, true, TissueLevel{nan, kReach}},
        {s, true, TissueLevel{200.0F, 0.0F}},
        {s, true, TissueLevel{200.0F, 1e9F}},
    };
    for (const Barrier& b : bad) {
        EXPECT_THROW(solver.addBarrier(b), std::invalid_argument);
    }
    EXPECT_TRUE(solver.barriers().empty());
}

} // namespace
} // namespace steerseg::test
