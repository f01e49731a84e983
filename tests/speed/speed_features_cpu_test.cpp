// The classifier features' CPU twin (speed/classifier_features_cpu, no GL): a scan's stored
// type and rescale give the features of its real values, as the GPU's texture holds them; bad
// input is refused. The twin against the GPU: speed_twins_test.cpp.
#include "speed/classifier_features_cpu.hpp"

#include <cstdint>
#include <gtest/gtest.h>
#include <stdexcept>
#include <vector>

namespace steerseg::test {
namespace {

TEST(SpeedFeaturesCpu, AScansStoredTypeAndRescaleGiveItsRealValuesFeatures) {
    Geometry g;
    g.dims = {11, 7, 6};
    Volume ct(VoxelType::Int16, g);
    ct.setRescale({0.5, -1024.0});
    std::int16_t next = 0;
    for (std::int16_t& v : ct.voxels<std::int16_t>()) {
        next = static_cast<std::int16_t>((next * 37 + 911) % 4001);
        v = next;
    }
    const std::vector<glm::ivec3> voxels{{0, 0, 0}, {10, 6, 5}, {5, 3, 2}, {9, 1, 4}};
    const std::vector<float> real = ct.realValues();
    const std::vector<float> fromScan = speed::cpuClassifierFeatures(ct, voxels);
    EXPECT_EQ(fromScan, speed::cpuClassifierFeatures(real, g.dims, voxels));
    ASSERT_EQ(fromScan.size(), voxels.size() * speed::kClassifierFeatureCount);
    EXPECT_EQ(fromScan[0], real[0]) << "feature 0 is the intensity";
}

TEST(SpeedFeaturesCpu, RefusesVoxelsOutsideAndIntensitiesThatDoNotFill) {
    const glm::ivec3 d{4, 4, 4};
    const std::vector<float> v(64, 1.0F);
    const std::vector<glm::ivec3> outside{{4, 0, 0}};
    EXPECT_THROW((void)speed::cpuClassifierFeatures(v, d, outside), std::invalid_argument);
    const std::vector<glm::ivec3> inside{{1, 1, 1}};
    EXPECT_THROW((void)speed::cpuClassifierFeatures(std::vector<float>(63), d, inside),
                 std::invalid_argument);
    const std::vector<float> flat = speed::cpuClassifierFeatures(v, d, inside);
    EXPECT_EQ(flat, (std::vector<float>{1, 1, 1, 1, 0, 0, 0, 0})) << "a flat scan";
}

} // namespace
} // namespace steerseg::test
