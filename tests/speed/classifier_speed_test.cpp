// The classification speed on the GPU (issue 13): features against a CPU computation, the
// GPU evaluation against the CPU forest, the two textures of one mean intensity, and the
// marks' vote where appearance cannot tell (issue 27).
#include "common/bindings.h"
#include "gpu/gl_handle.hpp"
#include "gpu/gl_state_guard.hpp"
#include "gpu/program.hpp"
#include "gpu/scan_texture.hpp"
#include "gpu/texture_readback.hpp"
#include "speed/classifier_features.hpp"
#include "speed/classifier_features_cpu.hpp"
#include "speed/classifier_speed.hpp"
#include "speed/classifier_speed_cpu.hpp"
#include "speed/place_vote.hpp"
#include "speed/split_mix.hpp"
#include "support/gpu_fixture.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <gtest/gtest.h>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

namespace steerseg::test {
using speed::ClassifierParams;
using speed::ClassifierSpeed;
using speed::Example;
using speed::kClassifierFeatureCount;
namespace {

class ClassifierSpeedTest : public GpuTest {};

std::size_t indexOf(glm::ivec3 d, glm::ivec3 v) {
    return static_cast<std::size_t>(v.x) +
           static_cast<std::size_t>(d.x) *
               (static_cast<std::size_t>(v.y) +
                static_cast<std::size_t>(d.y) * static_cast<std::size_t>(v.z));
}

// Uniform in [-1, 1], the same for a seed on every platform.
float noise(speed::SplitMix& rng) {
    return static_cast<float>(static_cast<double>(rng.next() >> 11U) * 0x1.0p-52 - 1.0);
}

// The features written out from their definitions, in double, with clamp to edge.
std::vector<double> cpuFeatures(const std::vector<float>& vol, glm::ivec3 d, glm::ivec3 v) {
    auto at = [&](glm::ivec3 p) {
        return static_cast<double>(vol[indexOf(d, glm::clamp(p, glm::ivec3(0), d - 1))]);
    };
    auto stats = [&](glm::ivec3 c, int reach, int step) {
        double s = 0.0;
        double q = 0.0;
        int n = 0;
        for (int z = -reach; z <= reach; z += step) {
            for (int y = -reach; y <= reach; y += step) {
                for (int x = -reach; x <= reach; x += step) {
                    const double value = at(c + glm::ivec3(x, y, z));
                    s += value;
                    q += value * value;
                    ++n;
                }
            }
        }
        const double mean = s / n;
        return std::pair{mean, std::sqrt(std::max(q / n - mean * mean, 0.0))};
    };
    const auto [m3, s3] = stats(v, 1, 1);
    const auto [m5, s5] = stats(v, 2, 1);
    const auto [m9, s9] = stats(v, 4, 2);
    glm::dvec3 g;
    for (int a = 0; a < 3; ++a) {
        glm::ivec3 e(0);
        e[a] = 1;
        g[a] = 0.5 * (stats(v + e, 1, 1).first - stats(v - e, 1, 1).first);
    }
    return {at(v), m3, m5, m9, s3, s5, s9, glm::length(g)};
}

// Values of a 3D R32F texture at the voxels given, through the product's one read-back path.
std::vector<float> readAt(GLuint texture, glm::ivec3 d, const std::vector<glm::ivec3>& voxels) {
    const std::vector<float> all = gpu::readVolumeTexture(texture, d);
    std::vector<float> values;
    values.reserve(voxels.size());
    for (const glm::ivec3 v : voxels) {
        values.push_back(all[indexOf(d, v)]);
    }
    return values;
}

std::vector<glm::ivec3> allVoxels(glm::ivec3 d) {
    std::vector<glm::ivec3> v;
    for (int k = 0; k < d.z; ++k) {
        for (int j = 0; j < d.y; ++j) {
            for (int i = 0; i < d.x; ++i) {
                v.emplace_back(i, j, k);
            }
        }
    }
    return v;
}

// The test: two textures of one mean intensity, calm noise for x < 24 and rough noise
// beyond, so that no threshold on the intensity tells them apart.
constexpr glm::ivec3 kTwoDims{48, 32, 32};
constexpr int kBorderX = 24;

std::vector<float> twoTextures() {
    speed::SplitMix rng(42);
    std::vector<float> v(static_cast<std::size_t>(kTwoDims.x) * kTwoDims.y * kTwoDims.z);
    for (const glm::ivec3 p : allVoxels(kTwoDims)) {
        v[indexOf(kTwoDims, p)] = 100.0F + (p.x < kBorderX ? 8.0F : 40.0F) * noise(rng);
    }
    return v;
}

const std::vector<Example> kCalm{{glm::vec3(10.0F, 16.0F, 16.0F), 6.0F}};
const std::vector<Example> kRough{{glm::vec3(37.0F, 16.0F, 16.0F), 6.0F}};

TEST_F(ClassifierSpeedTest, GpuFeaturesEqualACpuComputation) {
    const glm::ivec3 d{12, 10, 9};
    speed::SplitMix rng(1);
    std::vector<float> vol(static_cast<std::size_t>(d.x) * d.y * d.z);
    for (const glm::ivec3 p : allVoxels(d)) {
        vol[indexOf(d, p)] = 1000.0F + 20.0F * static_cast<float>(p.x) -
                             7.0F * static_cast<float>(p.z) + 15.0F * noise(rng);
    }
    const gpu::ScanTexture scan(vol, d);
    // Corners and edges (clamped neighbourhoods) and the middle.
    const std::vector<glm::ivec3> voxels{{0, 0, 0}, {11, 9, 8}, {5, 4, 4}, {1, 7, 3}, {6, 0, 8}};
    const std::vector<float> gpuValues = speed::gatherClassifierFeatures(scan.exact(), d, voxels);
    ASSERT_EQ(gpuValues.size(), voxels.size() * kClassifierFeatureCount);
    for (std::size_t n = 0; n < voxels.size(); ++n) {
        const std::vector<double> cpu = cpuFeatures(vol, d, voxels[n]);
        for (int f = 0; f < kClassifierFeatureCount; ++f) {
            const double gpuValue =
                gpuValues[n * kClassifierFeatureCount + static_cast<std::size_t>(f)];
            const double want = cpu[static_cast<std::size_t>(f)];
            EXPECT_NEAR(gpuValue, want, 1e-5 * 1000.0 + 1e-4 * std::abs(want))
                << "feature " << f << " at voxel " << n;
        }
    }
}

TEST_F(ClassifierSpeedTest, TwoTexturesMeetAtTheirBorder) {
    const std::vector<float> vol = twoTextures();
    const gpu::ScanTexture scan(vol, kTwoDims);
    const ClassifierSpeed speed(scan.exact(), kTwoDims, kCalm, kRough);
    const speed::ClassifierTraining& t = speed.training();
    EXPECT_EQ(t.insideSamples, t.insideCovered); // under the cap: every voxel
    EXPECT_GT(t.insideSamples, 800U);
    EXPECT_GT(t.outOfBagAccuracy, 0.95);

    const std::vector<float> out = readAt(speed.texture(), kTwoDims, allVoxels(kTwoDims));
    // Per slab of constant x: the share of voxels the speed calls inside.
    std::vector<double> insideShare(kTwoDims.x, 0.0);
    for (const glm::ivec3 p : allVoxels(kTwoDims)) {
        const float s = out[indexOf(kTwoDims, p)];
        ASSERT_GE(s, -1.0F);
        ASSERT_LE(s, 1.0F);
        insideShare[static_cast<std::size_t>(p.x)] += s > 0.0F ? 1.0 : 0.0;
    }
    double calm = 0.0;
    double rough = 0.0;
    int firstOutside = -1;
    for (int x = 0; x < kTwoDims.x; ++x) {
        double& share = insideShare[static_cast<std::size_t>(x)];
        share /= kTwoDims.y * kTwoDims.z;
        (x < kBorderX - 4 ? calm : rough) +=
            x < kBorderX - 4 ? share : (x >= kBorderX + 4 ? 1.0 - share : 0.0);
        if (firstOutside < 0 && share < 0.5) {
            firstOutside = x;
        }
    }
    EXPECT_GT(calm / (kBorderX - 4), 0.95);
    EXPECT_GT(rough / (kTwoDims.x - kBorderX - 4), 0.95);
    EXPECT_NEAR(firstOutside, kBorderX, 2);
}

TEST_F(ClassifierSpeedTest, GpuEvaluationMatchesTheCpuForest) {
    const std::vector<float> vol = twoTextures();
    const gpu::ScanTexture scan(vol, kTwoDims);
    ClassifierParams params;
    params.trees = 12;
    params.placeReach = 0.0F; // the forest alone (the marks' vote: below)
    // An inside sphere across the border: mixed leaves, so that the speed takes values between
    // -1 and 1 and a tree left out or walked wrongly shows.
    const std::vector<Example> straddling{{glm::vec3(22.0F, 16.0F, 16.0F), 6.0F}};
    const ClassifierSpeed speed(scan.exact(), kTwoDims, straddling, kRough, params);
    std::vector<glm::ivec3> voxels;
    speed::SplitMix rng(8);
    for (int n = 0; n < 300; ++n) {
        voxels.emplace_back(rng.below(kTwoDims.x), rng.below(kTwoDims.y), rng.below(kTwoDims.z));
    }
    voxels.emplace_back(0, 0, 0);
    voxels.push_back(kTwoDims - 1);
    const std::vector<float> features =
        speed::gatherClassifierFeatures(scan.exact(), kTwoDims, voxels);
    const std::vector<float> gpuValues = readAt(speed.texture(), kTwoDims, voxels);
    std::size_t near = 0;
    std::size_t between = 0;
    for (std::size_t n = 0; n < voxels.size(); ++n) {
        const float cpu = speed.forest().predict(
            std::span(features).subspan(n * kClassifierFeatureCount, kClassifierFeatureCount));
        near += std::abs(cpu - gpuValues[n]) <= 1e-6F ? 1 : 0;
        between += std::abs(cpu) < 0.9F ? 1 : 0;
    }
    EXPECT_EQ(near, voxels.size());
    EXPECT_GT(between, 10U);
}

// The walk alone, on the CPU twin's features (the numerics check's): the same branches, so the
// same looks as the CPU forest's, mixed ones included; rows of the wrong length are refused.
TEST_F(ClassifierSpeedTest, GpuWalkOnTheCpuFeaturesEqualsTheCpuForest) {
    const std::vector<float> vol = twoTextures();
    const gpu::ScanTexture scan(vol, kTwoDims);
    ClassifierParams params;
    params.trees = 12;
    params.evaluation = speed::ClassifierEvaluation::OnDemand;
    const std::vector<Example> straddling{{glm::vec3(22.0F, 16.0F, 16.0F), 6.0F}};
    const ClassifierSpeed speed(scan.exact(), kTwoDims, straddling, kRough, params);
    const std::vector<glm::ivec3> voxels = allVoxels(kTwoDims);
    const std::vector<float> features = speed::cpuClassifierFeatures(vol, kTwoDims, voxels);
    const std::vector<float> gpu = speed.walkOnGpu(features);
    const std::vector<float> cpu = speed::cpuForestLooks(speed.forest(), features);
    ASSERT_EQ(gpu.size(), voxels.size());
    std::size_t apart = 0;
    std::size_t mixed = 0;
    for (std::size_t n = 0; n < gpu.size(); ++n) {
        apart += std::abs(gpu[n] - cpu[n]) > 1e-6F ? 1 : 0;
        mixed += std::abs(cpu[n]) < 0.9F ? 1 : 0;
    }
    EXPECT_EQ(apart, 0U);
    EXPECT_GT(mixed, 10U) << "a walk that goes wrong shows on mixed leaves";
    EXPECT_TRUE(speed.walkOnGpu({}).empty());
    EXPECT_THROW((void)speed.walkOnGpu(std::span(features).first(kClassifierFeatureCount + 1)),
                 std::invalid_argument);
}

// One texture throughout, an inside mark at one end and an outside mark at the other: the
// forest cannot tell them apart (a coin's toss at every voxel), the marks' vote decides near
// each, and far from both the forest alone speaks, on the GPU as speed::placeVoteAt says.
TEST_F(ClassifierSpeedTest, WhereAppearanceIsUnsureTheNearestMarksDecide) {
    const glm::ivec3 d{96, 24, 24};
    speed::SplitMix rng(5);
    std::vector<float> vol(static_cast<std::size_t>(d.x) * d.y * d.z);
    for (float& v : vol) {
        v = 100.0F + 20.0F * noise(rng);
    }
    const gpu::ScanTexture scan(vol, d);
    const std::vector<Example> inside{{glm::vec3(12.0F, 12.0F, 12.0F), 4.0F}};
    const std::vector<Example> outside{{glm::vec3(84.0F, 12.0F, 12.0F), 4.0F}};
    ClassifierParams params;
    params.trees = 12;
    const ClassifierSpeed speed(scan.exact(), d, inside, outside, params);
    const std::vector<glm::ivec3> voxels = allVoxels(d);
    const std::vector<float> out = readAt(speed.texture(), d, voxels);
    const std::vector<float> features = speed::gatherClassifierFeatures(scan.exact(), d, voxels);
    // Shares called inside: within 6 voxels of each mark (its radius and a half), and beyond
    // both marks' reach.
    std::array<double, 3> insideCount{};
    std::array<double, 3> count{};
    double worst = 0.0;
    for (std::size_t n = 0; n < voxels.size(); ++n) {
        const float look = speed.forest().predict(
            std::span(features).subspan(n * kClassifierFeatureCount, kClassifierFeatureCount));
        const float want =
            speed::classifierSpeedFrom(look, speed::placeVoteAt(speed.placeVote(), voxels[n]));
        worst = std::max(worst, static_cast<double>(std::abs(want - out[n])));
        const glm::vec3 p(voxels[n]);
        const std::size_t where = glm::length(p - inside[0].centre) <= 6.0F    ? 0
                                  : glm::length(p - outside[0].centre) <= 6.0F ? 1
                                  : p.x >= 36.0F && p.x < 60.0F                ? 2
                                                                               : 3;
        if (where < 3) {
            count[where] += 1.0;
            insideCount[where] += out[n] > 0.0F ? 1.0 : 0.0;
        }
    }
    EXPECT_LT(worst, 0.01); // a half float's vote, filtered
    // The forest alone: 0.70 and 0.36 (its bootstrap has seen most of the marks' voxels); with
    // the vote 0.93 and 0.11.
    EXPECT_GT(insideCount[0] / count[0], 0.88);
    EXPECT_LT(insideCount[1] / count[1], 0.2);
    const double far = insideCount[2] / count[2]; // the forest's coin
    EXPECT_GT(far, 0.1);
    EXPECT_LT(far, 0.9);
}

TEST_F(ClassifierSpeedTest, EvaluatesEverySlabOfALongScan) {
    // More slices than one evaluation dispatch takes (64): calm below z = 35, rough above.
    const glm::ivec3 d{12, 12, 72};
    speed::SplitMix rng(6);
    std::vector<float> vol(static_cast<std::size_t>(d.x) * d.y * d.z);
    for (const glm::ivec3 p : allVoxels(d)) {
        vol[indexOf(d, p)] = 50.0F + (p.z < 35 ? 5.0F : 30.0F) * noise(rng);
    }
    const gpu::ScanTexture scan(vol, d);
    const std::vector<Example> calm{{glm::vec3(6.0F, 6.0F, 12.0F), 5.0F}};
    const std::vector<Example> rough{{glm::vec3(6.0F, 6.0F, 60.0F), 5.0F}};
    const ClassifierSpeed speed(scan.exact(), d, calm, rough);
    std::vector<glm::ivec3> last;
    for (const glm::ivec3 p : allVoxels(d)) {
        if (p.z >= 66) {
            last.push_back(p);
        }
    }
    std::size_t outside = 0;
    for (const float v : readAt(speed.texture(), d, last)) {
        outside += v < 0.0F ? 1 : 0;
    }
    EXPECT_GT(outside, last.size() * 9 / 10);
}

constexpr GLuint kClassifierBindings[] = {CLASSIFIER_SAMPLES_BINDING, CLASSIFIER_FEATURES_BINDING,
                                          CLASSIFIER_NODES_BINDING, CLASSIFIER_ROOTS_BINDING};

TEST_F(ClassifierSpeedTest, LeavesTheCallersGlStateAsItWas) {
    const std::vector<float> vol = twoTextures();
    const gpu::ScanTexture scan(vol, kTwoDims);
    const gpu::Buffer foreign =
        gpu::createBuffer(GL_SHADER_STORAGE_BUFFER, 64, nullptr, GL_STATIC_DRAW);
    const gpu::Texture image = gpu::createTexture();
    glBindTexture(GL_TEXTURE_3D, image.id());
    glTexStorage3D(GL_TEXTURE_3D, 1, GL_R32F, 2, 2, 2);
    glBindImageTexture(0, image.id(), 0, GL_TRUE, 0, GL_READ_ONLY, GL_R32F);
    glActiveTexture(GL_TEXTURE0);
    glBindTexture(GL_TEXTURE_3D, image.id());
    for (const GLuint binding : kClassifierBindings) {
        glBindBufferBase(GL_SHADER_STORAGE_BUFFER, binding, foreign.id());
    }
    const ClassifierSpeed speed(scan.exact(), kTwoDims, kCalm, kRough);
    GLint value = 0;
    for (const GLuint binding : kClassifierBindings) {
        glGetIntegeri_v(GL_SHADER_STORAGE_BUFFER_BINDING, binding, &value);
        EXPECT_EQ(static_cast<GLuint>(value), foreign.id()) << "SSBO binding " << binding;
    }
    glGetIntegeri_v(GL_IMAGE_BINDING_NAME, 0, &value);
    EXPECT_EQ(static_cast<GLuint>(value), image.id());
    glGetIntegerv(GL_TEXTURE_BINDING_3D, &value);
    EXPECT_EQ(static_cast<GLuint>(value), image.id());
    glGetIntegerv(GL_CURRENT_PROGRAM, &value);
    EXPECT_EQ(value, 0);
}

std::string refusal(GLuint texture, glm::ivec3 dims, const std::vector<Example>& inside,
                    const std::vector<Example>& outside, const ClassifierParams& params = {}) {
    try {
        const ClassifierSpeed speed(texture, dims, inside, outside, params);
    } catch (const std::invalid_argument& e) {
        return e.what();
    }
    return "accepted";
}

TEST_F(ClassifierSpeedTest, RefusesBadInputWithOneLine) {
    const glm::ivec3 d{16, 16, 16};
    const std::vector<float> vol(16 * 16 * 16, 5.0F);
    const gpu::ScanTexture scan(vol, d);
    const std::vector<Example> in{{glm::vec3(4.0F), 2.0F}};
    const std::vector<Example> out{{glm::vec3(12.0F), 2.0F}};
    EXPECT_EQ(refusal(scan.exact(), d, {}, out), "classifier speed: no inside examples");
    EXPECT_EQ(refusal(scan.exact(), d, in, {{glm::vec3(40.0F), 3.0F}}),
              "classifier speed: the outside examples cover no voxel of the scan (16x16x16)");
    EXPECT_NE(
        refusal(scan.exact(), d, {{glm::vec3(std::numeric_limits<float>::quiet_NaN()), 2.0F}}, out)
            .find("not a finite"),
        std::string::npos);
    EXPECT_EQ(refusal(scan.exact(), glm::ivec3(16, 16, 8), in, out),
              "classifier speed: the intensity texture is not R32F of 16x16x8 voxels");
    EXPECT_EQ(refusal(0, d, in, out), "classifier speed: the intensity texture is not a texture");
    ClassifierParams noSamples;
    noSamples.maxSamplesPerClass = 0;
    EXPECT_EQ(refusal(scan.exact(), d, in, out, noSamples),
              "classifier speed: samples per class must be in [1, 1048576]");
    ClassifierParams deep;
    deep.maxDepth = 40;
    EXPECT_EQ(refusal(scan.exact(), d, in, out, deep),
              "classifier speed: trees must be in [1, 256] and the depth in [1, 16]");
    // A flat scan: nothing tells the classes apart, but training still succeeds (neutral speed).
    EXPECT_EQ(refusal(scan.exact(), d, in, out), "accepted");
}

} // namespace
} // namespace steerseg::test
