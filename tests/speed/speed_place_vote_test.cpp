// The operator's marks as a vote of where (speed/place_vote, issue 27): each mark speaks near
// itself only, a stroke's overlapping dabs as one mark, and bad marks are refused.
#include "speed/place_vote.hpp"

#include <cmath>
#include <gtest/gtest.h>
#include <limits>
#include <stdexcept>
#include <vector>

namespace steerseg::test {
namespace {

using speed::Example;
using speed::placeVote;
using speed::placeVoteAt;
using speed::placeWeight;

constexpr glm::ivec3 kDims{64, 48, 40};

TEST(PlaceVote, AMarkWeighsOneWithinItsRadiusAndNothingBeyondItsReach) {
    EXPECT_FLOAT_EQ(placeWeight(0.0F, 4.0F, 3.0F), 1.0F);
    EXPECT_FLOAT_EQ(placeWeight(4.0F, 4.0F, 3.0F), 1.0F);
    EXPECT_FLOAT_EQ(placeWeight(8.0F, 4.0F, 3.0F), 0.5F); // halfway from the radius to 3 radii
    EXPECT_FLOAT_EQ(placeWeight(12.0F, 4.0F, 3.0F), 0.0F);
    EXPECT_FLOAT_EQ(placeWeight(30.0F, 4.0F, 3.0F), 0.0F);
    EXPECT_FLOAT_EQ(placeWeight(4.5F, 4.0F, 1.0F), 0.0F); // reach 1: the sphere alone
    EXPECT_FLOAT_EQ(placeWeight(0.4F, 0.0F, 3.0F), 1.0F); // a point mark holds its voxel
}

TEST(PlaceVote, InsideMarksVoteInOutsideMarksOutAndFarFromBothNobodyVotes) {
    const std::vector<Example> inside{{glm::vec3(14.0F, 20.0F, 20.0F), 4.0F}};
    const std::vector<Example> outside{{glm::vec3(50.0F, 20.0F, 20.0F), 4.0F}};
    const speed::PlaceVote vote = placeVote(inside, outside, kDims, 3.0F);
    EXPECT_EQ(vote.dims, glm::ivec3(16, 12, 10));
    ASSERT_EQ(vote.values.size(), 16U * 12U * 10U);
    EXPECT_NEAR(placeVoteAt(vote, {14, 20, 20}), 1.0F, 0.02F);
    EXPECT_NEAR(placeVoteAt(vote, {50, 20, 20}), -1.0F, 0.02F);
    EXPECT_GT(placeVoteAt(vote, {22, 20, 20}), 0.3F); // within the inside mark's reach
    EXPECT_LT(placeVoteAt(vote, {42, 20, 20}), -0.3F);
    EXPECT_EQ(placeVoteAt(vote, {32, 20, 20}), 0.0F); // 18 from each: beyond both reaches
    EXPECT_EQ(placeVoteAt(vote, {14, 20, 39}), 0.0F);
    EXPECT_EQ(placeVoteAt(vote, {0, 0, 0}), 0.0F);
    for (const float v : vote.values) {
        ASSERT_GE(v, -1.0F);
        ASSERT_LE(v, 1.0F);
    }
}

TEST(PlaceVote, OnThickSlicesAMarkReachesAsFarInMillimetresThroughTheSlices) {
    // Slices twice as thick as the pixels: the mark's 3 radii are 12 pixels and 6 slices.
    const std::vector<Example> inside{{glm::vec3(14.0F, 20.0F, 20.0F), 4.0F}};
    const speed::PlaceVote vote = placeVote(inside, {}, kDims, 3.0F, glm::vec3(1.0F, 1.0F, 2.0F));
    EXPECT_GT(placeVoteAt(vote, {14, 20, 20}), 0.8F);
    EXPECT_GT(placeVoteAt(vote, {22, 20, 20}), 0.3F);
    EXPECT_LT(placeVoteAt(vote, {14, 20, 28}), 0.15F); // 8 slices are 16 pixels away
    const speed::PlaceVote round = placeVote(inside, {}, kDims, 3.0F);
    EXPECT_GT(placeVoteAt(round, {14, 20, 28}), 0.3F);
}

TEST(PlaceVote, ReachOneKeepsEachMarkToItsSphereAndZeroLeavesAppearanceAlone) {
    const std::vector<Example> inside{{glm::vec3(14.0F, 20.0F, 20.0F), 4.0F}};
    const speed::PlaceVote sphere = placeVote(inside, {}, kDims, 1.0F);
    EXPECT_GT(placeVoteAt(sphere, {14, 20, 20}), 0.8F); // a cell's corner lies beyond the radius
    EXPECT_EQ(placeVoteAt(sphere, {24, 20, 20}), 0.0F);
    const speed::PlaceVote none = placeVote(inside, {}, kDims, 0.0F);
    for (const float v : none.values) {
        ASSERT_EQ(v, 0.0F);
    }
}

TEST(PlaceVote, AStrokesOverlappingDabsSpeakAsOneMark) {
    std::vector<Example> stroke;
    for (int n = 0; n < 200; ++n) {
        stroke.push_back({glm::vec3(30.0F + 0.01F * static_cast<float>(n), 24.0F, 20.0F), 3.0F});
    }
    const std::vector<Example> outside{{glm::vec3(38.0F, 24.0F, 20.0F), 3.0F}};
    const speed::PlaceVote many = placeVote(stroke, outside, kDims, 3.0F);
    const speed::PlaceVote one = placeVote(
        std::vector<Example>{{glm::vec3(31.99F, 24.0F, 20.0F), 3.0F}}, outside, kDims, 3.0F);
    for (const float v : many.values) {
        ASSERT_GE(v, -1.0F);
        ASSERT_LE(v, 1.0F);
    }
    // Between the two, the 200 dabs do not outvote the one outside mark.
    EXPECT_NEAR(placeVoteAt(many, {34, 24, 20}), placeVoteAt(one, {34, 24, 20}), 0.02F);
    EXPECT_LT(std::abs(placeVoteAt(many, {35, 24, 20})), 0.5F);
}

TEST(PlaceVote, MarksOutsideTheScanOrHugeCostNothingOrCoverIt) {
    const std::vector<Example> far{{glm::vec3(1e30F, -1e30F, 5.0F), 4.0F}};
    const speed::PlaceVote none = placeVote(far, far, kDims, 3.0F);
    for (const float v : none.values) {
        ASSERT_EQ(v, 0.0F);
    }
    const std::vector<Example> huge{{glm::vec3(10.0F), 1e30F}};
    const speed::PlaceVote all = placeVote(huge, {}, {5, 5, 5}, 3.0F);
    for (const float v : all.values) {
        ASSERT_EQ(v, 1.0F);
    }
}

TEST(PlaceVote, RefusesBadMarksAndSizes) {
    const float nan = std::numeric_limits<float>::quiet_NaN();
    const float inf = std::numeric_limits<float>::infinity();
    const std::vector<Example> ok{{glm::vec3(4.0F), 2.0F}};
    for (const Example bad :
         {Example{glm::vec3(nan, 1.0F, 1.0F), 2.0F}, Example{glm::vec3(1.0F, inf, 1.0F), 2.0F},
          Example{glm::vec3(1.0F), nan}, Example{glm::vec3(1.0F), -1.0F}}) {
        const std::vector<Example> marks{bad};
        EXPECT_THROW((void)placeVote(marks, ok, kDims, 3.0F), std::invalid_argument);
        EXPECT_THROW((void)placeVote(ok, marks, kDims, 3.0F), std::invalid_argument);
    }
    EXPECT_THROW((void)placeVote(ok, ok, {0, 4, 4}, 3.0F), std::invalid_argument);
    EXPECT_THROW((void)placeVote(ok, ok, kDims, -1.0F), std::invalid_argument);
    EXPECT_THROW((void)placeVote(ok, ok, kDims, nan), std::invalid_argument);
}

} // namespace
} // namespace steerseg::test
