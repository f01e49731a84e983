#include "steering/click_robot.hpp"

#include <cmath>
#include <gtest/gtest.h>
#include <random>

namespace steerseg::bench {
namespace {

std::size_t at(const MaskGrid& g, int i, int j, int k) {
    return static_cast<std::size_t>(i + g.dims.x * (j + g.dims.y * k));
}

std::vector<std::uint8_t> box(const MaskGrid& g, glm::ivec3 lo, glm::ivec3 hi) {
    std::vector<std::uint8_t> m(g.count(), 0);
    for (int k = lo.z; k <= hi.z; ++k) {
        for (int j = lo.y; j <= hi.y; ++j) {
            for (int i = lo.x; i <= hi.x; ++i) {
                m[at(g, i, j, k)] = 1;
            }
        }
    }
    return m;
}

TEST(ClickRobot, TheLargestComponentIs26Connected) {
    const MaskGrid g{{8, 8, 8}, {1, 1, 1}};
    std::vector<std::uint8_t> m(g.count(), 0);
    // Three voxels touching only at corners: one component of 3 under 26-connectivity ...
    m[at(g, 1, 1, 1)] = m[at(g, 2, 2, 2)] = m[at(g, 3, 3, 3)] = 1;
    // ... larger than a face-connected pair elsewhere.
    m[at(g, 6, 0, 0)] = m[at(g, 7, 0, 0)] = 1;
    const auto c = largestComponent(g, m);
    EXPECT_EQ(c[at(g, 2, 2, 2)], 1);
    EXPECT_EQ(c[at(g, 6, 0, 0)], 0);
}

TEST(ClickRobot, OfEqualComponentsTheFirstInStorageOrderWins) {
    const MaskGrid g{{8, 4, 4}, {1, 1, 1}};
    std::vector<std::uint8_t> m(g.count(), 0);
    m[at(g, 5, 0, 0)] = m[at(g, 6, 0, 0)] = 1; // first in storage order
    m[at(g, 0, 3, 3)] = m[at(g, 1, 3, 3)] = 1;
    const auto c = largestComponent(g, m);
    EXPECT_EQ(c[at(g, 5, 0, 0)], 1);
    EXPECT_EQ(c[at(g, 0, 3, 3)], 0);
}

// The challenge's box: the extent of every component of the label, corners inclusive.
TEST(ClickRobot, TheLabelsBoxHoldsEveryComponent) {
    const MaskGrid grid{{9, 7, 5}, {0.7, 0.9, 2.5}};
    std::vector<std::uint8_t> label(grid.count(), 0);
    EXPECT_FALSE(labelBox(grid, label).has_value());
    const auto at = [&](int i, int j, int k) -> std::uint8_t& {
        return label[static_cast<std::size_t>((k * grid.dims.y + j) * grid.dims.x + i)];
    };
    at(2, 3, 1) = 1;
    at(6, 1, 4) = 1; // a second component
    const std::optional<VoxelBox> box = labelBox(grid, label);
    ASSERT_TRUE(box.has_value());
    EXPECT_EQ(box->lo, glm::ivec3(2, 1, 1));
    EXPECT_EQ(box->hi, glm::ivec3(6, 3, 4));
}

TEST(ClickRobot, TheInitialClickIsTheDeepestVoxelInMillimetres) {
    // A box 11 voxels on each side, the slices twice as thin: the middle slice is deepest, 6
    // voxels (3 mm) from the nearest outside voxel along k; in it every voxel 3 mm or more from
    // the sides is as deep, and the first of them in storage order is the click.
    const MaskGrid g{{15, 15, 15}, {1.0, 1.0, 0.5}};
    const auto label = box(g, {2, 2, 2}, {12, 12, 12});
    const auto c = initialClick(g, label);
    ASSERT_TRUE(c);
    EXPECT_EQ(c->voxel, glm::ivec3(4, 4, 7));
    EXPECT_TRUE(c->positive);
    EXPECT_NEAR(c->depthMm, 3.0, 1e-6);
    EXPECT_EQ(c->componentVoxels, 11U * 11U * 11U);
    // The brush stays inside in mm: 3 mm, in voxels along the finest axis (0.5 mm).
    EXPECT_NEAR(brushRadius(g, *c, 100.0), 6.0, 1e-6);
    EXPECT_NEAR(brushRadius(g, *c, 2.0), 2.0, 1e-6);
}

// The challenge's evaluation takes the error's centre in voxel steps: on slices three times as
// thick as the pixels, an error 11 voxels on each side has one centre, its middle voxel, where
// in mm the whole middle column 6 mm from the sides ties and the first of it wins. The brush is
// sized in mm either way.
TEST(ClickRobot, TheChallengesCentreCountsVoxelStepsWhateverTheSpacing) {
    const MaskGrid g{{15, 15, 15}, {1.0, 1.0, 3.0}};
    const auto label = box(g, {2, 2, 2}, {12, 12, 12});
    const std::vector<std::uint8_t> empty(g.count(), 0);
    const auto steps = correctionClick(g, empty, label, DepthMeasure::VoxelSteps);
    ASSERT_TRUE(steps);
    EXPECT_EQ(steps->voxel, glm::ivec3(7, 7, 7));
    EXPECT_TRUE(steps->positive);
    EXPECT_NEAR(steps->depthMm, 6.0, 1e-6);
    const auto mm = correctionClick(g, empty, label, DepthMeasure::Millimetres);
    ASSERT_TRUE(mm);
    EXPECT_EQ(mm->voxel, glm::ivec3(7, 7, 3));
    EXPECT_NEAR(mm->depthMm, 6.0, 1e-6);
}

TEST(ClickRobot, TiesGoToTheFirstVoxelInStorageOrderAndTheGridEdgeIsABoundary) {
    // The whole grid, 4 x 5 x 5: the voxels beyond its edge are the boundary, so the deepest
    // are 2 voxels in from every face, (1..2, 1..3, 1..3), and the first of them wins.
    const MaskGrid g{{4, 5, 5}, {1, 1, 1}};
    const auto label = box(g, {0, 0, 0}, {3, 4, 4});
    const auto c = initialClick(g, label);
    ASSERT_TRUE(c);
    EXPECT_EQ(c->voxel, glm::ivec3(1, 1, 1));
    EXPECT_NEAR(c->depthMm, 2.0, 1e-6);
}

TEST(ClickRobot, CorrectionsClickTheLargestErrorWithItsSign) {
    const MaskGrid g{{20, 20, 20}, {1, 1, 1}};
    const auto label = box(g, {2, 2, 2}, {11, 11, 11});
    // The mask misses the label's upper half in k: a positive click there.
    auto mask = box(g, {2, 2, 2}, {11, 11, 6});
    auto c = correctionClick(g, mask, label);
    ASSERT_TRUE(c);
    EXPECT_TRUE(c->positive);
    EXPECT_GE(c->voxel.z, 7);
    // A larger leak beside it: a negative click in the leak.
    mask = label;
    const auto leak = box(g, {12, 2, 2}, {19, 19, 19});
    for (std::size_t v = 0; v < mask.size(); ++v) {
        mask[v] = static_cast<std::uint8_t>(mask[v] | leak[v]);
    }
    c = correctionClick(g, mask, label);
    ASSERT_TRUE(c);
    EXPECT_FALSE(c->positive);
    EXPECT_GE(c->voxel.x, 12);
    EXPECT_FALSE(correctionClick(g, label, label));
}

TEST(ClickRobot, DiceAndSurfaceDice) {
    const MaskGrid g{{30, 30, 30}, {1, 1, 1}};
    const auto a = box(g, {5, 5, 5}, {20, 20, 20});
    EXPECT_DOUBLE_EQ(dice(a, a), 1.0);
    EXPECT_DOUBLE_EQ(surfaceDice(g, a, a, 2.0), 1.0);
    // One voxel off: Dice below 1, but every surface voxel within 2 mm of the other surface.
    const auto b = box(g, {6, 5, 5}, {21, 20, 20});
    EXPECT_LT(dice(a, b), 1.0);
    EXPECT_DOUBLE_EQ(surfaceDice(g, a, b, 2.0), 1.0);
    // Five voxels off: the shifted faces are out of tolerance.
    const auto far = box(g, {10, 5, 5}, {25, 20, 20});
    EXPECT_LT(surfaceDice(g, a, far, 2.0), 0.9);
    const std::vector<std::uint8_t> empty(g.count(), 0);
    EXPECT_DOUBLE_EQ(surfaceDice(g, a, empty, 2.0), 0.0);
    EXPECT_DOUBLE_EQ(surfaceDice(g, empty, empty, 2.0), 1.0);
    EXPECT_DOUBLE_EQ(dice(empty, empty), 1.0);
}

TEST(ClickRobot, PaintedSpheresAndTheAucOfTheFirstSixPredictions) {
    const MaskGrid g{{11, 11, 11}, {1, 1, 1}};
    std::vector<std::uint8_t> m(g.count(), 0);
    paintSphere(g, m, {5, 5, 5}, 2.0, 1);
    EXPECT_EQ(m[at(g, 5, 5, 7)], 1);
    EXPECT_EQ(m[at(g, 5, 5, 8)], 0);
    EXPECT_EQ(m[at(g, 6, 6, 6)], 1); // sqrt(3) <= 2
    paintSphere(g, m, {5, 5, 5}, 1.0, 0);
    EXPECT_EQ(m[at(g, 5, 5, 5)], 0);
    // On 2 mm slices the sphere is round in mm: 4 pixels across, 2 slices through.
    const MaskGrid thick{{11, 11, 11}, {0.5, 0.5, 1.0}};
    std::vector<std::uint8_t> t(thick.count(), 0);
    paintSphere(thick, t, {5, 5, 5}, 4.0, 1);
    EXPECT_EQ(t[at(thick, 9, 5, 5)], 1);
    EXPECT_EQ(t[at(thick, 5, 5, 7)], 1);
    EXPECT_EQ(t[at(thick, 5, 5, 8)], 0);
    EXPECT_EQ(t[at(thick, 5, 9, 6)], 0); // (4, 2) steps are sqrt(16 + 4) > 4
    EXPECT_DOUBLE_EQ(diceAuc({0.5, 0.5, 0.5, 0.5, 0.5, 0.5, 0.9}), 2.5);
    EXPECT_DOUBLE_EQ(diceAuc({0.0, 1.0}), 0.5);
    EXPECT_DOUBLE_EQ(diceAuc({0.7}), 0.0);
}

// The challenge's scores over the corrections, not the initial prompt; an NSD where the DSC is
// 0.2 or less counts 0.
TEST(ClickRobot, ChallengeScoresFollowTheChallengesDefinitions) {
    const std::vector<double> dsc{0.1, 0.5, 0.15, 0.8, 0.9, 0.9, 0.99};
    const std::vector<double> nsd{0.2, 0.6, 0.7, 0.85, 0.95, 1.0, 1.0};
    const ChallengeScores s = challengeScores(dsc, nsd);
    EXPECT_DOUBLE_EQ(s.dscAuc, 0.5 * (0.5 + 0.15) + 0.5 * (0.15 + 0.8) + 0.5 * (0.8 + 0.9) +
                                   0.5 * (0.9 + 0.9));
    EXPECT_DOUBLE_EQ(s.nsdAuc, 0.5 * (0.6 + 0.0) + 0.5 * (0.0 + 0.85) + 0.5 * (0.85 + 0.95) +
                                   0.5 * (0.95 + 1.0));
    EXPECT_DOUBLE_EQ(s.finalDsc, 0.9);
    EXPECT_DOUBLE_EQ(s.finalNsd, 1.0);
    const ChallengeScores perfect =
        challengeScores(std::vector<double>(6, 1.0), std::vector<double>(6, 1.0));
    EXPECT_DOUBLE_EQ(perfect.dscAuc, 4.0) << "at most 4 over five steps";
    EXPECT_DOUBLE_EQ(challengeScores({0.5}, {0.5}).finalDsc, 0.0) << "no correction yet";
}

} // namespace
} // namespace steerseg::bench
