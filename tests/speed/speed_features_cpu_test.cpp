// The classifier features' CPU twin (speed/classifier_features_cpu, no GL): a scan's stored
// type and rescale give the features of its real values, as the GPU's texture holds them; bad
// input is refused. The twin against the GPU: speed_twins_test.cpp.
#include "speed/classifier_features_cpu.hpp"

#include <cmath>
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

// Features that step s voxels at voxel v are the voxel-step features of every s-th voxel at v / s:
// a 0.5 mm series reads the windows a 1 mm scan of the same tissue would.
TEST(SpeedFeaturesCpu, AStrideReadsTheWindowsOfTheCoarserGrid) {
    const glm::ivec3 fine{40, 36, 12};
    const glm::ivec3 stride{2, 3, 1};
    const glm::ivec3 coarse = fine / stride;
    std::vector<float> v(static_cast<std::size_t>(fine.x * fine.y * fine.z));
    for (std::size_t n = 0; n < v.size(); ++n) {
        v[n] = static_cast<float>((n * 7919U) % 1009U);
    }
    std::vector<float> sub;
    for (int k = 0; k < coarse.z; ++k) {
        for (int j = 0; j < coarse.y; ++j) {
            for (int i = 0; i < coarse.x; ++i) {
                sub.push_back(v[linearIndex(fine, i * stride.x, j * stride.y, k * stride.z)]);
            }
        }
    }
    // Away from the edges, where clamping would read other voxels on the two grids.
    const std::vector<glm::ivec3> at{{5, 5, 5}, {14, 7, 6}, {10, 6, 7}};
    std::vector<glm::ivec3> fineAt;
    for (const glm::ivec3& c : at) {
        fineAt.push_back(c * stride);
    }
    EXPECT_EQ(speed::cpuClassifierFeatures(v, fine, fineAt, stride),
              speed::cpuClassifierFeatures(sub, coarse, at));
    EXPECT_NE(speed::cpuClassifierFeatures(v, fine, fineAt),
              speed::cpuClassifierFeatures(sub, coarse, at));
    EXPECT_THROW((void)speed::cpuClassifierFeatures(v, fine, fineAt, glm::ivec3(1, 0, 1)),
                 std::invalid_argument);
}

TEST(SpeedFeaturesCpu, TheStrideIsAboutAMillimetreAndNeverBelowAVoxel) {
    using speed::classifierFeatureStride;
    EXPECT_EQ(classifierFeatureStride({0.33, 0.30, 1.6}), glm::ivec3(3, 3, 1));
    EXPECT_EQ(classifierFeatureStride({0.4, 0.4, 0.4}), glm::ivec3(3));
    EXPECT_EQ(classifierFeatureStride({0.49, 0.49, 3.27}), glm::ivec3(2, 2, 1));
    EXPECT_EQ(classifierFeatureStride({0.98, 0.98, 3.27}), glm::ivec3(1)) << "the shared scans";
    EXPECT_EQ(classifierFeatureStride({0.737, 0.737, 0.737}), glm::ivec3(1));
    EXPECT_EQ(classifierFeatureStride({0.01, 1.0, 1.0}), glm::ivec3(16, 1, 1)) << "at most 16";
    EXPECT_EQ(classifierFeatureStride({0.0, -1.0, std::nan("")}), glm::ivec3(1));
}

} // namespace
} // namespace steerseg::test
