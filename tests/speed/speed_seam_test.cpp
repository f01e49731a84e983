// The edge speed against the threshold speed on the case: a noisy sphere beside a
// touching sphere of the same intensity, a thin dark seam between them. The threshold speed
// needs an eps wide enough to cross the noise, and then crosses the seam where the noise opens
// it; the edge speed on the smoothed scan stops at the seam. And both new speeds against the
// CPU reference, which reads the same per-voxel factor.
#include "gpu/scan_texture.hpp"
#include "solver/level_set_solver.hpp"
#include "solver/reference_solver.hpp"
#include "speed/edge_factor.hpp"
#include "speed/smoothing.hpp"
#include "support/gpu_fixture.hpp"
#include "support/solver_test_support.hpp"

#include <cmath>
#include <gtest/gtest.h>
#include <random>
#include <stdexcept>

namespace steerseg::test {
using namespace steerseg::solver; // the solver under test
using namespace steerseg::model;
namespace {

class SpeedSeamTest : public GpuTest {};

constexpr glm::ivec3 kDims{48, 26, 26};
constexpr glm::vec3 kCentreA{15.0F, 13.0F, 13.0F};
constexpr glm::vec3 kCentreB{33.0F, 13.0F, 13.0F};
constexpr float kRadius = 10.0F; // the spheres overlap in a disc of radius 4.4 at the seam
constexpr int kSeam = 24;        // the plane i = kSeam is dark where the spheres meet
constexpr float kHigh = 100.0F;
constexpr float kNoise = 20.0F;

bool inSphere(const glm::vec3& c, int i, int j, int k) {
    return glm::length(glm::vec3(i, j, k) - c) <= kRadius;
}

std::vector<float> twoSpheres() {
    std::mt19937 engine(11);
    std::uniform_real_distribution<float> u(1e-7F, 1.0F);
    std::vector<float> v(countOf(kDims));
    for (int k = 0; k < kDims.z; ++k) {
        for (int j = 0; j < kDims.y; ++j) {
            for (int i = 0; i < kDims.x; ++i) {
                const bool sphere =
                    i != kSeam && (inSphere(kCentreA, i, j, k) || inSphere(kCentreB, i, j, k));
                const float n =
                    std::sqrt(-2.0F * std::log(u(engine))) * std::cos(6.2831853F * u(engine));
                v[voxelIndex(kDims, i, j, k)] = (sphere ? kHigh : 0.0F) + kNoise * n;
            }
        }
    }
    return v;
}

// Sphere A as a mask (its side of the seam), and the count of sphere B's voxels inside `mask`.
std::vector<std::uint8_t> sphereA() {
    std::vector<std::uint8_t> m(countOf(kDims), 0);
    for (int k = 0; k < kDims.z; ++k) {
        for (int j = 0; j < kDims.y; ++j) {
            for (int i = 0; i < kSeam; ++i) {
                m[voxelIndex(kDims, i, j, k)] = inSphere(kCentreA, i, j, k) ? 1 : 0;
            }
        }
    }
    return m;
}

double fractionOfBFilled(const std::vector<std::uint8_t>& mask) {
    double in = 0.0;
    double all = 0.0;
    for (int k = 0; k < kDims.z; ++k) {
        for (int j = 0; j < kDims.y; ++j) {
            for (int i = kSeam + 1; i < kDims.x; ++i) {
                if (inSphere(kCentreB, i, j, k)) {
                    all += 1.0;
                    in += mask[voxelIndex(kDims, i, j, k)];
                }
            }
        }
    }
    return in / all;
}

const Sphere kSeed{kCentreA, 4.0F};
constexpr int kMaxIterations = 1500;
// The threshold speed has crossed the seam by then; the edge speed converges at t = 1.9 (224
// iterations) with the mask in sphere A (Dice 0.998, nothing of B).
constexpr float kLeakTime = 1.0F;

TEST_F(SpeedSeamTest, ThresholdWideEnoughForTheNoiseLeaksThroughTheSeam) {
    LevelSetSolver solver(twoSpheres(), kDims);
    solver.addSphere(kSeed);
    solver.setParams({kHigh, 3.5F * kNoise, 0.9F});
    (void)solver.evolveUntil(kLeakTime, kMaxIterations);
    EXPECT_GT(fractionOfBFilled(solver.readMask()), 0.5);
}

TEST_F(SpeedSeamTest, EdgeSpeedOnTheSmoothedScanStopsAtTheSeam) {
    LevelSetSolver solver(twoSpheres(), kDims);
    const gpu::Texture smoothed =
        speed::smoothScan(solver.scan().exact(), kDims, {10, 3.0F * kNoise});
    const gpu::Texture factor = speed::edgeFactor(smoothed.id(), kDims, kNoise);
    solver.setSpeedInputs({model::SpeedKind::Edge, smoothed.id(), factor.id(), {}});
    solver.addSphere(kSeed);
    solver.setParams({kHigh, 2.0F * kNoise, 0.9F});
    const StepResult r = solver.runUntilConverged(kMaxIterations);
    EXPECT_TRUE(r.converged);
    const std::vector<std::uint8_t> mask = solver.readMask();
    EXPECT_GE(dice(mask, sphereA()), 0.9);
    EXPECT_LT(fractionOfBFilled(mask), 0.05);
}

TEST_F(SpeedSeamTest, SpeedInputsWithoutTheirFactorAreRefused) {
    LevelSetSolver solver(twoSpheres(), kDims);
    EXPECT_THROW(solver.setSpeedInputs({model::SpeedKind::Edge, 0, 0, {}}), std::invalid_argument);
    EXPECT_THROW(solver.setSpeedInputs({model::SpeedKind::Classify, 0, 0, {}}),
                 std::invalid_argument);
}

// A factor field on the ball case of the agreement test: the edge factor in [0.2, 1], the
// classifier's output in [-1, 1] (positive in the ball, varying along i).
std::vector<float> factorField(const glm::ivec3& d, model::SpeedKind kind) {
    std::vector<float> f(countOf(d));
    for (int k = 0; k < d.z; ++k) {
        for (int j = 0; j < d.y; ++j) {
            for (int i = 0; i < d.x; ++i) {
                const float wave = 0.5F + 0.5F * std::sin(static_cast<float>(i + 2 * j) / 5.0F);
                const float r = glm::length(glm::vec3(i, j, k) - glm::vec3(24, 22, 20));
                f[voxelIndex(d, i, j, k)] = kind == model::SpeedKind::Edge
                                                ? 0.2F + 0.8F * wave
                                                : (r < 15.0F ? 0.3F + 0.7F * wave : -0.8F);
            }
        }
    }
    return f;
}

// The GPU solver and the reference, their speeds set, 40 steps from `seed`: the same front.
void expectStepsAgree(LevelSetSolver& gpu, ReferenceSolver& cpu, const Sphere& seed,
                      const LevelSetParams& params) {
    gpu.addSphere(seed);
    gpu.setParams(params);
    cpu.addSphere(seed);
    cpu.setParams(params);
    const StepResult r = gpu.step(40);
    EXPECT_EQ(cpu.step(40), 40);
    EXPECT_NEAR(r.evolvedTime, cpu.evolvedTime(), 1e-3F * cpu.evolvedTime());
    const std::vector<std::uint8_t> g = gpu.readMask();
    const std::vector<std::uint8_t> c = cpu.mask();
    EXPECT_GT(insideCount(c), insideCount(std::vector<std::uint8_t>(c.size(), 0)));
    EXPECT_GE(dice(g, c), 0.99) << "gpu " << insideCount(g) << " cpu " << insideCount(c);
    EXPECT_EQ(differencesOffSurface(cpu.dims(), g, c), 0U);
}

TEST_F(SpeedSeamTest, EdgeAndClassifySpeedsMatchTheReference) {
    const glm::ivec3 d{48, 44, 40};
    const auto volume = ballVolume(d, 0.0F, 100.0F, {24, 22, 20}, 15.0F);
    const Sphere seed{{22, 20, 19}, 4.0F};
    for (const model::SpeedKind kind : {model::SpeedKind::Edge, model::SpeedKind::Classify}) {
        SCOPED_TRACE(model::speedKindName(kind));
        const LevelSetParams params{100.0F, 30.0F, 0.7F};
        const std::vector<float> field = factorField(d, kind);
        const gpu::ScanTexture factor(field, d); // an R32F texture of the field
        LevelSetSolver gpu(volume, d);
        gpu.setSpeedInputs({kind, 0, factor.exact(), {}});
        ReferenceSolver cpu(volume, d);
        cpu.setSpeed(kind, field);
        expectStepsAgree(gpu, cpu, seed, params);
    }
}

// Classify within the window (the console's bound, docs/speed.md): a forest sure of "inside"
// everywhere but in the slab i >= 30, on the ball at T +- eps. The bounded speed grows in the ball
// only and stops at the slab; the GPU's and the reference's agree.
TEST_F(SpeedSeamTest, ClassifyWithinTheWindowMatchesTheReferenceAndStaysInIt) {
    const glm::ivec3 d{48, 44, 40};
    const glm::vec3 centre{24, 22, 20};
    const auto volume = ballVolume(d, 0.0F, 100.0F, centre, 15.0F);
    std::vector<float> field(countOf(d));
    for (int k = 0; k < d.z; ++k) {
        for (int j = 0; j < d.y; ++j) {
            for (int i = 0; i < d.x; ++i) {
                field[voxelIndex(d, i, j, k)] = i >= 30 ? -0.9F : 0.9F;
            }
        }
    }
    const gpu::ScanTexture factor(field, d);
    const Sphere seed{{20, 22, 20}, 4.0F};
    const LevelSetParams params{100.0F, 30.0F, 0.7F};
    LevelSetSolver gpu(volume, d);
    gpu.setSpeedInputs({model::SpeedKind::Classify, 0, factor.exact(), {}, true});
    ReferenceSolver cpu(volume, d);
    cpu.setSpeed(model::SpeedKind::Classify, field, true);
    expectStepsAgree(gpu, cpu, seed, params);

    EXPECT_TRUE(gpu.runUntilConverged(1500).converged);
    const std::vector<std::uint8_t> mask = gpu.readMask();
    std::size_t beyond = 0;
    std::size_t deepInBall = 0;
    std::size_t deepTaken = 0;
    for (int k = 0; k < d.z; ++k) {
        for (int j = 0; j < d.y; ++j) {
            for (int i = 0; i < d.x; ++i) {
                const bool in = mask[voxelIndex(d, i, j, k)] != 0;
                const float r2 = glm::length(glm::vec3(i, j, k) - centre);
                beyond += in && (r2 > 16.0F || i > 30) ? 1U : 0U;
                if (r2 < 14.0F && i < 29) {
                    ++deepInBall;
                    deepTaken += in ? 1U : 0U;
                }
            }
        }
    }
    EXPECT_EQ(beyond, 0U) << "the window and the forest's slab bound it";
    EXPECT_GT(deepTaken, deepInBall * 95 / 100) << deepTaken << " of " << deepInBall;
}

TEST_F(SpeedSeamTest, OnlyClassifyIsBoundedByTheWindow) {
    LevelSetSolver solver(twoSpheres(), kDims);
    const gpu::ScanTexture factor(std::vector<float>(countOf(kDims), 1.0F), kDims);
    EXPECT_THROW(solver.setSpeedInputs({model::SpeedKind::Edge, 0, factor.exact(), {}, true}),
                 std::invalid_argument);
}

} // namespace
} // namespace steerseg::test
