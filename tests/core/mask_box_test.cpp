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

} // namespace
} // namespace steerseg
