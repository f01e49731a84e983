// --probe's rules (session/speed_probe.hpp) on synthetic volumes: the noise estimate follows the
// noise and ignores a smooth ramp, the suggestions follow their documented factors and floors.
#include "session/speed_probe.hpp"

#include <cmath>
#include <gtest/gtest.h>
#include <random>
#include <stdexcept>

namespace steerseg::test {
namespace {

constexpr glm::ivec3 kDims{40, 40, 40};

// 100 + ramp * i + Gaussian noise of std `noise` (Box-Muller on a fixed engine).
Volume noisyVolume(float noise, float ramp) {
    Geometry g;
    g.dims = kDims;
    Volume v(VoxelType::Float32, g);
    std::mt19937 engine(3);
    std::uniform_real_distribution<float> u(1e-7F, 1.0F);
    const auto voxels = v.voxels<float>();
    for (int k = 0; k < kDims.z; ++k) {
        for (int j = 0; j < kDims.y; ++j) {
            for (int i = 0; i < kDims.x; ++i) {
                const float n =
                    std::sqrt(-2.0F * std::log(u(engine))) * std::cos(6.2831853F * u(engine));
                voxels[v.linearIndex(i, j, k)] = 100.0F + ramp * static_cast<float>(i) + noise * n;
            }
        }
    }
    return v;
}

const model::Sphere kProbe{{20.0F, 20.0F, 20.0F}, 6.0F};

TEST(SpeedProbe, NoiseFollowsTheNoiseNotTheStructure) {
    const session::SpeedProbe flat = session::probeSpeed(noisyVolume(20.0F, 0.0F), kProbe);
    EXPECT_NEAR(flat.noise, 20.0, 1.5);
    EXPECT_NEAR(flat.stddev, 20.0, 1.5);
    EXPECT_NEAR(flat.mean, 100.0, 2.0);
    // A ramp of 8 per voxel raises the std to ~29 (8 r / sqrt(5) from the ramp) but the
    // neighbour differences barely (sqrt(20^2 + 8^2 / 6) = 20.3).
    const session::SpeedProbe ramp = session::probeSpeed(noisyVolume(20.0F, 8.0F), kProbe);
    EXPECT_GT(ramp.stddev, 27.0);
    EXPECT_NEAR(ramp.noise, 20.3, 1.5);
}

TEST(SpeedProbe, SuggestionsFollowTheRulesAndTheirFloors) {
    const session::SpeedProbe p = session::probeSpeed(noisyVolume(20.0F, 0.0F), kProbe);
    EXPECT_DOUBLE_EQ(p.T, p.mean);
    EXPECT_DOUBLE_EQ(p.eps, session::kEpsFactor * p.stddev);
    EXPECT_DOUBLE_EQ(p.conductance, session::kConductanceFactor * p.noise);
    EXPECT_DOUBLE_EQ(p.kappa, session::kKappaFactor * p.noise);
    // A noiseless region: eps at its floor, conductance and kappa from the noise floor.
    const session::SpeedProbe clean = session::probeSpeed(noisyVolume(0.0F, 0.0F), kProbe);
    EXPECT_DOUBLE_EQ(clean.eps, session::kEpsFloor);
    EXPECT_DOUBLE_EQ(clean.kappa, session::kKappaFactor * session::kNoiseFloor);
    EXPECT_GT(clean.conductance, 0.0);
}

TEST(SpeedProbe, SpheresThatDoNotFitAreRefused) {
    const Volume v = noisyVolume(5.0F, 0.0F);
    EXPECT_THROW((void)session::probeSpeed(v, {{50.0F, 20.0F, 20.0F}, 3.0F}),
                 std::invalid_argument);
    EXPECT_THROW((void)session::probeSpeed(v, {{20.0F, 20.0F, 20.0F}, 0.4F}),
                 std::invalid_argument);
    EXPECT_THROW((void)session::probeSpeed(v, {{20.0F, 20.0F, 20.0F}, NAN}), std::invalid_argument);
}

} // namespace
} // namespace steerseg::test
