#include "cli/args.hpp"
#include "mask_dice.hpp"
#include "mask_stats.hpp"
#include "model/level_set_params.hpp"
#include "seed_level_set.hpp"
#include "synthetic_ball.hpp"
#include "threshold_level_set.hpp"

#include <gtest/gtest.h>
#include <vector>

namespace steerseg::itkbench {
namespace {

using test::syntheticBall;
using test::thresholdMask;

TEST(ItkSeedLevelSet, SignedDistanceToUnionOfSpheresNegativeInside) {
    const FloatImage::Pointer grid = syntheticBall(5.0, 1.0F, 0.0F);
    const std::vector<Seed> seeds{{8, 8, 8, 3}, {20, 8, 8, 2}};
    const FloatImage::Pointer phi = seedLevelSet(grid, seeds, SeedSpheres::Voxels);
    EXPECT_FLOAT_EQ(phi->GetPixel({{8, 8, 8}}), -3.0F);
    EXPECT_FLOAT_EQ(phi->GetPixel({{11, 8, 8}}), 0.0F);
    EXPECT_FLOAT_EQ(phi->GetPixel({{20, 8, 8}}), -2.0F);
    EXPECT_FLOAT_EQ(phi->GetPixel({{14, 8, 8}}), 3.0F); // nearer the first sphere
    // Radius in voxels whatever the spacing (2 mm along i here).
    EXPECT_FLOAT_EQ(phi->GetPixel({{8, 11, 8}}), 0.0F);
}

TEST(ItkSeedLevelSet, SpheresRoundInMillimetresAsTheProductDrawsThem) {
    // 2 mm along i, 1 mm along j and k: a radius of 3 reaches 3 voxels along j, 1.5 along i.
    const FloatImage::Pointer grid = syntheticBall(5.0, 1.0F, 0.0F);
    const std::vector<Seed> seeds{{8, 8, 8, 3}};
    const FloatImage::Pointer phi = seedLevelSet(grid, seeds);
    EXPECT_FLOAT_EQ(phi->GetPixel({{8, 11, 8}}), 0.0F);
    EXPECT_LT(phi->GetPixel({{9, 8, 8}}), 0.0F);
    EXPECT_GT(phi->GetPixel({{10, 8, 8}}), 0.0F);
    // The product's own distance, voxel for voxel.
    const model::Sphere sphere{glm::vec3(8.0F), 3.0F};
    const glm::vec3 scale = model::sphereScale({2.0, 1.0, 1.0});
    for (const glm::ivec3 v : {glm::ivec3(10, 8, 8), glm::ivec3(9, 10, 7), glm::ivec3(12, 3, 9)}) {
        EXPECT_FLOAT_EQ(phi->GetPixel({{v.x, v.y, v.z}}),
                        model::sphereDistance(sphere, glm::vec3(v), scale));
    }
}

TEST(ItkSeedLevelSet, RejectsBadSeeds) {
    const FloatImage::Pointer grid = syntheticBall(5.0, 1.0F, 0.0F);
    const std::vector<Seed> outside{{40, 8, 8, 3}};
    EXPECT_THROW(seedLevelSet(grid, outside), std::runtime_error);
    EXPECT_THROW(seedLevelSet(grid, {}), std::runtime_error);
    EXPECT_THROW(parseSeed("1,2,3,0"), cli::UsageError);
    EXPECT_THROW(parseSeed("1,2,3"), cli::UsageError);
    EXPECT_THROW(parseSeed("1,2,x,4"), cli::UsageError);
    const Seed s = parseSeed("1.5,2,3,4");
    EXPECT_DOUBLE_EQ(s.i, 1.5);
    EXPECT_DOUBLE_EQ(s.r, 4.0);
}

LevelSetParams ballParams(StopRule stop) {
    LevelSetParams p;
    p.target = 100.0;
    p.epsilon = 20.0;
    p.alpha = 0.8;
    p.stop = stop;
    p.iterations = 2000;
    return p;
}

TEST(ItkThresholdLevelSet, FindsTheBallInVoxelUnits) {
    // Speed eps - |I - T| = 0 where I = 80, i.e. at radius 8.5 on the ramp.
    const FloatImage::Pointer scan = syntheticBall(10.0, 100.0F, 0.0F, 5.0);
    const std::vector<Seed> seeds{{16, 16, 16, 3}};
    LevelSetParams p = ballParams(StopRule::Iterations);
    p.iterations = 300;
    const LevelSetResult r = runThresholdLevelSet(scan, seeds, p);
    EXPECT_GT(maskDice(r.mask, thresholdMask(scan, 80.0F)).dice, 0.95);
    // UseImageSpacing is off: a ball in index space, though voxels are 2 mm along i.
    auto extent = [&](unsigned axis) {
        int n = 0;
        MaskImage::IndexType idx{{16, 16, 16}};
        for (int x = 0; x < 32; ++x) {
            idx[axis] = x;
            n += r.mask->GetPixel(idx);
        }
        return n;
    };
    EXPECT_EQ(extent(0), extent(1));
    EXPECT_EQ(extent(0), extent(2));
}

TEST(ItkThresholdLevelSet, ConvergenceIsItsRmsCriterion) {
    // At rest the front voxels still hop by up to 1/6 voxel per step (ITK scales the step to the
    // fastest front voxel), so the RMS change of the active layer stays near 0.1 here: ITK's
    // default 0.02 is never met on this ramp and the cap stops the run.
    const FloatImage::Pointer scan = syntheticBall(10.0, 100.0F, 0.0F, 5.0);
    const std::vector<Seed> seeds{{16, 16, 16, 3}};
    LevelSetParams p = ballParams(StopRule::Converge);
    p.iterations = 500;
    const LevelSetResult capped = runThresholdLevelSet(scan, seeds, p);
    EXPECT_FALSE(capped.converged);
    EXPECT_EQ(capped.iterations, 500);
    EXPECT_GT(capped.rmsChange, 0.02);
    p.maxRmsChange = 0.3;
    const LevelSetResult loose = runThresholdLevelSet(scan, seeds, p);
    EXPECT_TRUE(loose.converged);
    EXPECT_LT(loose.iterations, 500);
    EXPECT_LT(loose.rmsChange, 0.3);
}

TEST(ItkThresholdLevelSet, TimeLimitIsHitExactlyAndIterationsCounted) {
    const FloatImage::Pointer scan = syntheticBall(12.0, 100.0F, 0.0F);
    const std::vector<Seed> seeds{{16, 16, 16, 3}};
    LevelSetParams p = ballParams(StopRule::Time);
    p.time = 0.1;
    const LevelSetResult timed = runThresholdLevelSet(scan, seeds, p);
    EXPECT_NEAR(timed.evolvedTime, 0.1, 1e-12);
    EXPECT_FALSE(timed.converged);

    LevelSetParams q = ballParams(StopRule::Iterations);
    q.iterations = 7;
    const LevelSetResult counted = runThresholdLevelSet(scan, seeds, q);
    EXPECT_EQ(counted.iterations, 7);
}

TEST(ItkThresholdLevelSet, PurePropagationStepIsOneSixthVoxelOverMaxSpeed) {
    // alpha = 1: no curvature, so ITK's step is WaveDT / max|alpha * speed| with WaveDT = 1/6 in
    // 3D; inside the ball the speed is eps - |I - T| = eps everywhere on the front.
    const FloatImage::Pointer scan = syntheticBall(12.0, 100.0F, 0.0F);
    const std::vector<Seed> seeds{{16, 16, 16, 3}};
    LevelSetParams p = ballParams(StopRule::Iterations);
    p.alpha = 1.0;
    p.iterations = 5;
    const LevelSetResult r = runThresholdLevelSet(scan, seeds, p);
    EXPECT_NEAR(r.evolvedTime, 5.0 / (6.0 * 20.0), 1e-6);
}

TEST(ItkThresholdLevelSet, NegativeSpeedShrinksTheSeed) {
    // Everything is far outside T +/- eps: the speed is negative and the inside (phi < 0) shrinks.
    const FloatImage::Pointer scan = syntheticBall(12.0, 100.0F, 0.0F);
    const std::vector<Seed> seeds{{16, 16, 16, 5}};
    LevelSetParams p = ballParams(StopRule::Iterations);
    p.target = 1000.0;
    p.iterations = 10;
    const LevelSetResult shrunk = runThresholdLevelSet(scan, seeds, p);
    p.target = 100.0;
    const LevelSetResult grown = runThresholdLevelSet(scan, seeds, p);
    const long long seedVoxels = 515; // lattice points within 5 of the centre
    EXPECT_LT(shrunk.insideVoxels, seedVoxels);
    EXPECT_GT(grown.insideVoxels, seedVoxels);
}

TEST(ItkThresholdLevelSet, RejectsBadParameters) {
    const FloatImage::Pointer scan = syntheticBall(12.0, 100.0F, 0.0F);
    const std::vector<Seed> seeds{{16, 16, 16, 3}};
    LevelSetParams p = ballParams(StopRule::Converge);
    p.epsilon = 0.0;
    EXPECT_THROW(runThresholdLevelSet(scan, seeds, p), cli::UsageError);
    p = ballParams(StopRule::Converge);
    p.alpha = 1.5;
    EXPECT_THROW(runThresholdLevelSet(scan, seeds, p), cli::UsageError);
    p = ballParams(StopRule::Time);
    p.time = -1.0;
    EXPECT_THROW(runThresholdLevelSet(scan, seeds, p), cli::UsageError);
}

TEST(ItkMaskDice, CountsOverlapAndRefusesOtherGrids) {
    const FloatImage::Pointer big = syntheticBall(10.0, 1.0F, 0.0F);
    const FloatImage::Pointer small = syntheticBall(5.0, 1.0F, 0.0F);
    const MaskImage::Pointer a = thresholdMask(big, 0.5F);
    const MaskImage::Pointer b = thresholdMask(small, 0.5F);
    EXPECT_DOUBLE_EQ(maskDice(a, a).dice, 1.0);
    const DiceResult d = maskDice(a, b);
    EXPECT_EQ(d.overlap, d.bVoxels); // the small ball lies inside the big one
    EXPECT_NEAR(d.dice,
                2.0 * static_cast<double>(d.bVoxels) / static_cast<double>(d.aVoxels + d.bVoxels),
                1e-12);
    const MaskImage::Pointer shifted = thresholdMask(small, 0.5F);
    MaskImage::PointType origin;
    origin.Fill(3.0);
    shifted->SetOrigin(origin);
    EXPECT_THROW(maskDice(a, shifted), std::runtime_error);
}

TEST(ItkMaskStats, MeanStdAndADeepSeed) {
    const FloatImage::Pointer scan = syntheticBall(8.0, 100.0F, 0.0F);
    const MaskImage::Pointer mask = thresholdMask(scan, 50.0F);
    const MaskStats s = maskStats(scan, mask);
    EXPECT_DOUBLE_EQ(s.mean, 100.0);
    EXPECT_NEAR(s.std, 0.0, 1e-9);
    EXPECT_TRUE(s.centroidInside);
    EXPECT_EQ(s.deepest[0], 16);
    EXPECT_EQ(s.deepest[1], 16);
    EXPECT_EQ(s.deepest[2], 16);
    EXPECT_GT(s.depth, 6.0); // to the nearest border voxel of the mask, not past it
    EXPECT_GT(s.probeVoxels, 100);
    EXPECT_DOUBLE_EQ(s.probeMean, 100.0);
    EXPECT_DOUBLE_EQ(s.seed.r, 3.0);
}

} // namespace
} // namespace steerseg::itkbench
