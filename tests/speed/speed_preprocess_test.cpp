// The speed's preprocessing on the GPU: the edge-preserving smoothing (against a plain box blur)
// and the edge-stopping factor, on a noisy step edge.
#include "gpu/scan_texture.hpp"
#include "gpu/texture_readback.hpp"
#include "speed/edge_factor.hpp"
#include "speed/smoothing.hpp"
#include "support/gpu_fixture.hpp"
#include "support/solver_test_support.hpp"

#include <cmath>
#include <gtest/gtest.h>
#include <random>
#include <stdexcept>

namespace steerseg::test {
namespace {

class SpeedPreprocessTest : public GpuTest {};

constexpr glm::ivec3 kDims{32, 24, 24};
constexpr int kStep = 16; // i < kStep: 0, else 100
constexpr float kHigh = 100.0F;
constexpr float kNoise = 10.0F;
constexpr double kHighD = kHigh;
constexpr double kNoiseD = kNoise;

// Gaussian noise by Box-Muller on a fixed engine: the same volume with every standard library.
std::vector<float> noisyStep() {
    std::mt19937 engine(7);
    std::uniform_real_distribution<float> u(1e-7F, 1.0F);
    std::vector<float> v(countOf(kDims));
    for (int k = 0; k < kDims.z; ++k) {
        for (int j = 0; j < kDims.y; ++j) {
            for (int i = 0; i < kDims.x; ++i) {
                const float n =
                    std::sqrt(-2.0F * std::log(u(engine))) * std::cos(6.2831853F * u(engine));
                v[voxelIndex(kDims, i, j, k)] = (i < kStep ? 0.0F : kHigh) + kNoise * n;
            }
        }
    }
    return v;
}

double at(const std::vector<float>& v, int i, int j, int k) {
    return static_cast<double>(
        v[voxelIndex(kDims, std::clamp(i, 0, kDims.x - 1), std::clamp(j, 0, kDims.y - 1),
                     std::clamp(k, 0, kDims.z - 1))]);
}

std::vector<float> boxBlur(const std::vector<float>& v) {
    std::vector<float> out(v.size());
    for (int k = 0; k < kDims.z; ++k) {
        for (int j = 0; j < kDims.y; ++j) {
            for (int i = 0; i < kDims.x; ++i) {
                double s = 0.0;
                for (int c = -1; c <= 1; ++c) {
                    for (int b = -1; b <= 1; ++b) {
                        for (int a = -1; a <= 1; ++a) {
                            s += at(v, i + a, j + b, k + c);
                        }
                    }
                }
                out[voxelIndex(kDims, i, j, k)] = static_cast<float>(s / 27.0);
            }
        }
    }
    return out;
}

// Standard deviation in the flat regions (3 voxels and more from the step and the borders).
double flatNoise(const std::vector<float>& v) {
    double sum = 0.0;
    double sumSq = 0.0;
    double n = 0.0;
    for (int k = 3; k < kDims.z - 3; ++k) {
        for (int j = 3; j < kDims.y - 3; ++j) {
            for (int i = 3; i < kDims.x - 3; ++i) {
                if (std::abs(i - kStep) < 3 && std::abs(i + 1 - kStep) < 3) {
                    continue;
                }
                const double x = at(v, i, j, k) - (i < kStep ? 0.0 : kHighD);
                sum += x;
                sumSq += x * x;
                n += 1.0;
            }
        }
    }
    return std::sqrt(sumSq / n - (sum / n) * (sum / n));
}

// The mean jump between the last low and the first high voxel: 100 for a sharp step.
double stepJump(const std::vector<float>& v) {
    double s = 0.0;
    for (int k = 0; k < kDims.z; ++k) {
        for (int j = 0; j < kDims.y; ++j) {
            s += at(v, kStep, j, k) - at(v, kStep - 1, j, k);
        }
    }
    return s / (kDims.y * kDims.z);
}

// Mean of v over the columns i in [lo, hi].
double meanOver(const std::vector<float>& v, int lo, int hi) {
    double s = 0.0;
    double n = 0.0;
    for (int k = 0; k < kDims.z; ++k) {
        for (int j = 0; j < kDims.y; ++j) {
            for (int i = lo; i <= hi; ++i) {
                s += at(v, i, j, k);
                n += 1.0;
            }
        }
    }
    return s / n;
}

TEST_F(SpeedPreprocessTest, SmoothingRemovesNoiseAndKeepsTheStep) {
    const std::vector<float> raw = noisyStep();
    const gpu::ScanTexture scan(raw, kDims);
    int calls = 0;
    const gpu::Texture smoothed =
        speed::smoothScan(scan.exact(), kDims, {10, 3.0F * kNoise}, [&](int done, int total) {
            ++calls;
            EXPECT_EQ(done, calls);
            EXPECT_EQ(total, 10);
        });
    EXPECT_EQ(calls, 10);
    const std::vector<float> pm = gpu::readVolumeTexture(smoothed.id(), kDims);
    const std::vector<float> box = boxBlur(raw);
    const double rawNoise = flatNoise(raw);
    EXPECT_NEAR(rawNoise, kNoiseD, 0.5);
    // The noise drops a lot in the flat regions, as under a box blur ...
    EXPECT_LT(flatNoise(pm), 0.35 * rawNoise) << "box " << flatNoise(box);
    // ... while the step stays sharp, where the box blur spreads it over three voxels.
    EXPECT_GT(stepJump(pm), 0.85 * kHighD) << "box " << stepJump(box);
    EXPECT_LT(stepJump(box), 0.45 * kHighD);
}

TEST_F(SpeedPreprocessTest, NoIterationsGivesNoTextureAndBadParametersAreRefused) {
    const std::vector<float> raw = noisyStep();
    const gpu::ScanTexture scan(raw, kDims);
    EXPECT_FALSE(speed::smoothScan(scan.exact(), kDims, {0, 0.0F}));
    EXPECT_THROW((void)speed::smoothScan(scan.exact(), kDims, {5, 0.0F}), std::invalid_argument);
    EXPECT_THROW((void)speed::smoothScan(scan.exact(), kDims, {-1, 10.0F}), std::invalid_argument);
    EXPECT_THROW((void)speed::smoothScan(scan.exact(), kDims, {5, NAN}), std::invalid_argument);
    EXPECT_THROW((void)speed::edgeFactor(scan.exact(), kDims, 0.0F), std::invalid_argument);
    EXPECT_THROW((void)speed::edgeFactor(scan.exact(), kDims, INFINITY), std::invalid_argument);
}

TEST_F(SpeedPreprocessTest, EdgeFactorIsSmallAtTheStepAndNearOneWhereFlat) {
    const gpu::ScanTexture scan(noisyStep(), kDims);
    const gpu::Texture smoothed = speed::smoothScan(scan.exact(), kDims, {10, 3.0F * kNoise});
    const gpu::Texture factor = speed::edgeFactor(smoothed.id(), kDims, kNoise);
    const std::vector<float> g = gpu::readVolumeTexture(factor.id(), kDims);
    for (const float x : g) {
        ASSERT_TRUE(x > 0.0F && x <= 1.0F) << x;
    }
    EXPECT_LT(meanOver(g, kStep - 1, kStep), 0.1);
    EXPECT_GT(meanOver(g, 3, kStep - 4), 0.8);
    EXPECT_GT(meanOver(g, kStep + 3, kDims.x - 4), 0.8);
}

} // namespace
} // namespace steerseg::test
