#include "core/volume.hpp"

#include <gtest/gtest.h>
#include <limits>

namespace steerseg::test {
namespace {

TEST(Volume, RejectsNonPositiveDims) {
    Geometry g;
    g.dims = {4, 0, 4};
    EXPECT_THROW(Volume(VoxelType::UInt8, g), std::invalid_argument);
}

TEST(Volume, StatsAreInRescaledUnits) {
    Geometry g;
    g.dims = {2, 2, 1};
    Volume v(VoxelType::Int16, g);
    auto vox = v.voxels<std::int16_t>();
    vox[0] = 0;
    vox[1] = 1000;
    vox[2] = 2000;
    vox[3] = 3000;
    v.setRescale({1.0, -1024.0});
    EXPECT_DOUBLE_EQ(v.stats().min, -1024.0);
    EXPECT_DOUBLE_EQ(v.stats().max, 3000.0 - 1024.0);
    EXPECT_DOUBLE_EQ(v.stats().mean, 1500.0 - 1024.0);
    EXPECT_EQ(v.stats().histogram.front(), 1U);
    EXPECT_EQ(v.stats().histogram.back(), 1U);
    EXPECT_DOUBLE_EQ(v.valueAt(1, 1, 0), 3000.0 - 1024.0);
}

TEST(Volume, NegativeSlopeSwapsRangeEnds) {
    Geometry g;
    g.dims = {2, 1, 1};
    Volume v(VoxelType::UInt8, g);
    v.voxels<std::uint8_t>()[1] = 10;
    v.setRescale({-2.0, 0.0});
    EXPECT_DOUBLE_EQ(v.stats().min, -20.0);
    EXPECT_DOUBLE_EQ(v.stats().max, 0.0);
}

// The extremes of a linear map lie at the ends of the stored range: both ends are checked,
// whichever sign the slope has.
TEST(Volume, RescaleProblemNamesWhatIsWrong) {
    const double nan = std::numeric_limits<double>::quiet_NaN();
    const double inf = std::numeric_limits<double>::infinity();
    EXPECT_EQ(rescaleProblem({1.0, -1024.0}, -2000.0, 3000.0), "");
    EXPECT_EQ(rescaleProblem({nan, 0.0}, 0.0, 1.0), "slope is nan");
    EXPECT_EQ(rescaleProblem({1.0, -inf}, 0.0, 1.0), "intercept is -inf");
    EXPECT_EQ(rescaleProblem({1e36, 0.0}, 0.0, 1000.0),
              "slope 1e+36 and intercept 0 take stored 1000 to 1e+39, beyond float32's range");
    EXPECT_NE(rescaleProblem({1e36, 0.0}, -1000.0, 0.0).find("take stored -1000 to -1e+39"),
              std::string::npos);
    EXPECT_NE(rescaleProblem({-1e36, 0.0}, 0.0, 1000.0).find("beyond float32's range"),
              std::string::npos);
    EXPECT_NE(rescaleProblem({1.0, 1e300}, 0.0, 0.0).find("take stored 0 to 1e+300"),
              std::string::npos);
    EXPECT_EQ(rescaleProblem({1e35, 0.0}, 0.0, 1000.0), ""); // 1e38 fits float32
}

TEST(Volume, StoredRangeIgnoresTheRescale) {
    Geometry g;
    g.dims = {3, 1, 1};
    Volume v(VoxelType::Int16, g);
    v.voxels<std::int16_t>()[0] = -7;
    v.voxels<std::int16_t>()[2] = 12;
    v.setRescale({2.0, 100.0});
    EXPECT_EQ(v.storedRange(), std::make_pair(-7.0, 12.0));
}

TEST(Geometry, IndexWorldRoundTripWithObliqueDirection) {
    Geometry g;
    g.dims = {10, 10, 10};
    g.spacing = {0.5, 0.7, 2.0};
    g.origin = {-10.0, 5.0, 3.0};
    const double c = std::cos(0.3);
    const double s = std::sin(0.3);
    g.direction =
        glm::dmat3(glm::dvec3(c, s, 0.0), glm::dvec3(-s, c, 0.0), glm::dvec3(0.0, 0.0, 1.0));
    const glm::dvec3 idx(3.0, 4.0, 5.0);
    const glm::dvec3 w = g.indexToWorld(idx);
    const glm::dvec3 back = g.worldToIndex(w);
    EXPECT_NEAR(back.x, 3.0, 1e-12);
    EXPECT_NEAR(back.y, 4.0, 1e-12);
    EXPECT_NEAR(back.z, 5.0, 1e-12);
    // Row-major: element (0,1) is the x component of the j axis.
    EXPECT_DOUBLE_EQ(g.directionRowMajor()[1], -s);
    EXPECT_DOUBLE_EQ(g.directionRowMajor()[3], s);
}

} // namespace
} // namespace steerseg::test
