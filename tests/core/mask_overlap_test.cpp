#include "core/mask_overlap.hpp"

#include <gtest/gtest.h>
#include <stdexcept>

namespace steerseg::test {
namespace {

Volume labels(glm::ivec3 dims) {
    Geometry g;
    g.dims = dims;
    return Volume(VoxelType::UInt8, g);
}

TEST(MaskOverlap, CountsTheLabelsVoxelsAndAgreement) {
    Volume ref = labels({4, 2, 1}); // labels 0 0 1 1 2 2 2 0
    const std::uint8_t values[] = {0, 0, 1, 1, 2, 2, 2, 0};
    std::copy(std::begin(values), std::end(values), ref.voxels<std::uint8_t>().begin());
    const std::vector<std::uint8_t> mask = {0, 1, 1, 0, 1, 1, 0, 0};

    const MaskOverlap one = maskOverlap(mask, ref, 1);
    EXPECT_EQ(one.mask, 4u);
    EXPECT_EQ(one.reference, 2u);
    EXPECT_EQ(one.both, 1u);
    EXPECT_DOUBLE_EQ(one.dice(), 2.0 / 6.0);
    const MaskOverlap any = maskOverlap(mask, ref, -1); // every non-zero label
    EXPECT_EQ(any.reference, 5u);
    EXPECT_EQ(any.both, 3u);
    EXPECT_DOUBLE_EQ(any.dice(), 6.0 / 9.0);
    // The label's real value counts, not the stored one.
    ref.setRescale({2.0, 0.0});
    EXPECT_EQ(maskOverlap(mask, ref, 4).reference, 3u);
    EXPECT_EQ(maskOverlap(mask, ref, 2).reference, 2u);

    EXPECT_DOUBLE_EQ(maskOverlap(std::vector<std::uint8_t>(8, 0), ref, 9).dice(), 1.0);
    EXPECT_THROW(maskOverlap(std::vector<std::uint8_t>(7, 0), ref, 1), std::invalid_argument);
    EXPECT_THROW(maskOverlap(labels({2, 4, 1}), ref, 1), std::invalid_argument);
    EXPECT_DOUBLE_EQ(maskOverlap(ref, ref, -1).dice(), 1.0);
}

TEST(MaskOverlap, TheReferencesVoxelsAreTheOnesItCounts) {
    Volume ref = labels({4, 2, 1});
    const std::uint8_t values[] = {0, 0, 1, 1, 2, 2, 2, 0};
    std::copy(std::begin(values), std::end(values), ref.voxels<std::uint8_t>().begin());
    ref.setRescale({2.0, 0.0}); // real values 0 0 2 2 4 4 4 0
    EXPECT_EQ(referenceVoxels(ref, 4), (std::vector<std::uint8_t>{0, 0, 0, 0, 1, 1, 1, 0}));
    EXPECT_EQ(referenceVoxels(ref, -1), (std::vector<std::uint8_t>{0, 0, 1, 1, 1, 1, 1, 0}));
    EXPECT_EQ(referenceVoxels(ref, 1), std::vector<std::uint8_t>(8, 0));
    // A mask of exactly those voxels agrees with the reference completely.
    EXPECT_DOUBLE_EQ(maskOverlap(referenceVoxels(ref, 2), ref, 2).dice(), 1.0);
}

} // namespace
} // namespace steerseg::test
