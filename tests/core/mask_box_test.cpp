// The box a mask's voxels lie in (core/mask_box).
#include "core/mask_box.hpp"
#include "core/volume.hpp"

#include <gtest/gtest.h>
#include <stdexcept>
#include <vector>

namespace steerseg {
namespace {

TEST(MaskBox, TheInclusiveBoxOfTheVoxelsOrNoneForAnEmptyMask) {
    const glm::ivec3 dims{7, 5, 4};
    std::vector<std::uint8_t> mask(7 * 5 * 4, 0);
    EXPECT_FALSE(maskBox(dims, mask).has_value());
    mask[linearIndex(dims, 5, 1, 2)] = 1;
    mask[linearIndex(dims, 2, 4, 1)] = 3;
    const std::optional<MaskBox> box = maskBox(dims, mask);
    ASSERT_TRUE(box.has_value());
    EXPECT_EQ(box->lo, glm::ivec3(2, 1, 1));
    EXPECT_EQ(box->hi, glm::ivec3(5, 4, 2));
    EXPECT_THROW((void)maskBox(dims, std::vector<std::uint8_t>(139, 1)), std::invalid_argument);
}

// Grown within the grid, and the mask cut to a box on the box's own grid.
TEST(MaskBox, GrowsWithinTheGridAndCropsTheMaskToIt) {
    const glm::ivec3 dims{7, 5, 4};
    const MaskBox grown = grownWithin(MaskBox{{1, 0, 2}, {5, 3, 3}}, 2, dims);
    EXPECT_EQ(grown.lo, glm::ivec3(0, 0, 0));
    EXPECT_EQ(grown.hi, glm::ivec3(6, 4, 3));
    EXPECT_EQ(boxDims(grown), dims);

    std::vector<std::uint8_t> mask(7 * 5 * 4, 0);
    mask[linearIndex(dims, 3, 2, 1)] = 1;
    const MaskBox box{{2, 2, 1}, {4, 3, 1}};
    const std::vector<float> cut = cropMask(dims, mask, box, -1.0F, 2.0F);
    ASSERT_EQ(cut.size(), 6U);
    EXPECT_EQ(cut, (std::vector<float>{2.0F, -1.0F, 2.0F, 2.0F, 2.0F, 2.0F}));
}

} // namespace
} // namespace steerseg
