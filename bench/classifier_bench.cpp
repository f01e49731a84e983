// Classification speed benchmark (docs/speed.md): the training split (sample voxels, their
// features from the CPU twin on the host scan as the console computes them, with the GPU's
// gather of the same samples timed and compared beside it, forest on the CPU) and the evaluation at
// every voxel, on a synthetic textured phantom of N^3 voxels, or on a real scan with examples
// given. Prints a markdown table. Not a test: figures depend on the machine (llvmpipe on a shared
// 2-core box is slow and noisy; run it alone).
//   classifier_bench [--size N] [--train-size N] [--trees N] [--depth N] [--samples N]
//                    [--repeat N] [--scan PATH --inside i,j,k,r --outside i,j,k,r ...
//                     [--truth MASK]]
// --train-size times the training alone (no evaluation) on a larger phantom, so that the
// interactive part is measured at 256^3 even where evaluating that many voxels on a software
// rasteriser takes minutes.
#include "bench/bench_scan.hpp"
#include "gpu/gpu_info.hpp"
#include "gpu/scan_texture.hpp"
#include "gpu/texture_readback.hpp"
#include "platform/egl/offscreen_context.hpp"
#include "speed/classifier_features.hpp"
#include "speed/classifier_features_cpu.hpp"
#include "speed/classifier_speed.hpp"
#include "speed/example_voxels.hpp"
#include "speed/random_forest.hpp"
#include "speed/split_mix.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <stdexcept>
#include <string>
#include <vector>

using namespace steerseg;

namespace {

int argOr(int argc, char** argv, const std::string& name, int fallback) {
    for (int i = 1; i + 1 < argc; ++i) {
        if (argv[i] == name) {
            return std::atoi(argv[i + 1]);
        }
    }
    return fallback;
}

std::string textOr(int argc, char** argv, const std::string& name, const std::string& fallback) {
    for (int i = 1; i + 1 < argc; ++i) {
        if (argv[i] == name) {
            return argv[i + 1];
        }
    }
    return fallback;
}

std::vector<speed::Example> examplesOf(int argc, char** argv, const std::string& name) {
    std::vector<speed::Example> out;
    for (int i = 1; i + 1 < argc; ++i) {
        if (argv[i] == name) {
            speed::Example e;
            if (std::sscanf(argv[i + 1], "%f,%f,%f,%f", &e.centre.x, &e.centre.y, &e.centre.z,
                            &e.radius) != 4) {
                throw std::runtime_error(name + " wants i,j,k,r");
            }
            out.push_back(e);
        }
    }
    return out;
}

// A rough-textured ball (the structure) in calm tissue of the same mean, beside a bright calm
// slab (a second outside tissue): no threshold on intensity separates the ball.
struct Phantom {
    glm::ivec3 dims;
    std::vector<float> intensity;
    std::vector<std::uint8_t> truth;
    std::vector<speed::Example> inside;
    std::vector<speed::Example> outside;
};

Phantom phantom(int n) {
    Phantom p;
    p.dims = glm::ivec3(n);
    const auto count = static_cast<std::size_t>(n) * n * n;
    p.intensity.resize(count);
    p.truth.resize(count);
    const glm::vec3 centre(static_cast<float>(n) * 0.4F);
    const float radius = static_cast<float>(n) * 0.25F;
    speed::SplitMix rng(1);
    std::size_t at = 0;
    for (int k = 0; k < n; ++k) {
        for (int j = 0; j < n; ++j) {
            for (int i = 0; i < n; ++i, ++at) {
                const float u =
                    static_cast<float>(static_cast<double>(rng.next() >> 11U) * 0x1.0p-52 - 1.0);
                const bool ball = glm::length(glm::vec3(i, j, k) - centre) <= radius;
                const bool slab = i > n * 3 / 4;
                p.intensity[at] = ball ? 100.0F + 40.0F * u : (slab ? 160.0F : 100.0F) + 8.0F * u;
                p.truth[at] = ball ? 1 : 0;
            }
        }
    }
    const float r = static_cast<float>(n) * 0.1F;
    p.inside = {{centre, r}};
    p.outside = {{glm::vec3(static_cast<float>(n) * 0.4F, static_cast<float>(n) * 0.4F,
                            static_cast<float>(n) * 0.85F),
                  r},
                 {glm::vec3(static_cast<float>(n) * 0.88F, static_cast<float>(n) * 0.5F,
                            static_cast<float>(n) * 0.5F),
                  r}};
    return p;
}

// The phantom as a scan on the host, as the console holds one.
Volume volumeOf(const Phantom& p) {
    Geometry g;
    g.dims = p.dims;
    Volume volume(VoxelType::Float32, g);
    std::copy(p.intensity.begin(), p.intensity.end(), volume.voxels<float>().begin());
    volume.invalidateStats();
    return volume;
}

double secondsSince(std::chrono::steady_clock::time_point t) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - t).count();
}

// Training alone (what the operator waits for before the evaluation starts), median of repeats.
void timeTraining(const Phantom& p, const speed::ClassifierParams& params, int repeat) {
    const Volume volume = volumeOf(p);
    const gpu::ScanTexture scan(volume);
    speed::ForestParams forest;
    forest.trees = params.trees;
    forest.maxDepth = params.maxDepth;
    forest.seed = params.seed;
    std::vector<double> features; // the console's: the CPU twin on the host scan
    std::vector<double> gather;   // the GPU's gather of the same samples, for comparison
    std::vector<double> train;
    std::size_t samples = 0;
    double accuracy = 0.0;
    for (int r = 0; r < repeat; ++r) {
        auto t = std::chrono::steady_clock::now();
        const auto cap = static_cast<std::size_t>(params.maxSamplesPerClass);
        const speed::ExampleVoxels in = speed::exampleVoxels(p.inside, p.dims, cap, 1, "inside");
        const speed::ExampleVoxels out = speed::exampleVoxels(p.outside, p.dims, cap, 2, "outside");
        std::vector<glm::ivec3> voxels = in.voxels;
        voxels.insert(voxels.end(), out.voxels.begin(), out.voxels.end());
        const std::vector<float> f = speed::cpuClassifierFeatures(volume, voxels);
        features.push_back(secondsSince(t));
        t = std::chrono::steady_clock::now();
        (void)speed::gatherClassifierFeatures(scan.exact(), p.dims, voxels);
        gather.push_back(secondsSince(t));
        t = std::chrono::steady_clock::now();
        std::vector<std::uint8_t> labels(voxels.size(), 0);
        std::fill(labels.begin(), labels.begin() + static_cast<std::ptrdiff_t>(in.voxels.size()),
                  1);
        const speed::RandomForest trained =
            speed::RandomForest::train(f, labels, speed::kClassifierFeatureCount, forest);
        train.push_back(secondsSince(t));
        samples = voxels.size();
        accuracy = trained.outOfBagAccuracy();
    }
    std::sort(features.begin(), features.end());
    std::sort(gather.begin(), gather.end());
    std::sort(train.begin(), train.end());
    std::fprintf(stderr, "%d^3: the GPU's gather of the same samples %.3f s (median)\n", p.dims.x,
                 gather[gather.size() / 2]);
    std::printf("| %d^3 training only | %zu | %.3f | %.3f | - | %.3f | - |\n", p.dims.x, samples,
                features[features.size() / 2], train[train.size() / 2], accuracy);
}

// What the GPU's gather returns for the training samples against the CPU twin the training now
// uses (issue 47: the H100's gather handed the forest other samples' features).
void compareGather(const gpu::ScanTexture& scan, const Volume& volume, const std::string& label,
                   const std::vector<speed::Example>& inside,
                   const std::vector<speed::Example>& outside,
                   const speed::ClassifierParams& params) {
    const auto cap = static_cast<std::size_t>(params.maxSamplesPerClass);
    std::vector<glm::ivec3> voxels =
        speed::exampleVoxels(inside, scan.dims(), cap, 1, "inside").voxels;
    const std::vector<glm::ivec3> out =
        speed::exampleVoxels(outside, scan.dims(), cap, 2, "outside").voxels;
    voxels.insert(voxels.end(), out.begin(), out.end());
    const std::vector<float> gpu =
        speed::gatherClassifierFeatures(scan.exact(), scan.dims(), voxels);
    const std::vector<float> cpu = speed::cpuClassifierFeatures(volume, voxels);
    double largest = 0.0;
    for (std::size_t n = 0; n < cpu.size(); ++n) {
        largest =
            std::max(largest, std::abs(static_cast<double>(gpu[n]) - static_cast<double>(cpu[n])));
    }
    std::fprintf(
        stderr,
        "%s: gathered features against the CPU twin: largest difference %g over %zu samples\n",
        label.c_str(), largest, voxels.size());
}

void timeWhole(const gpu::ScanTexture& scan, const Volume& volume, const std::string& label,
               const std::vector<speed::Example>& inside,
               const std::vector<speed::Example>& outside, const speed::ClassifierParams& params,
               int repeat, const std::vector<std::uint8_t>* truth) {
    compareGather(scan, volume, label, inside, outside, params);
    std::vector<speed::ClassifierTraining> runs;
    double agreement = -1.0;
    double dice = -1.0;
    for (int r = 0; r < repeat; ++r) {
        // As the console trains it: the samples' features from the scan on the host.
        const speed::ClassifierSpeed s(scan.exact(), scan.dims(), inside, outside, params, {},
                                       &volume);
        runs.push_back(s.training());
        if (truth != nullptr && r == 0) {
            // The sign against the phantom's truth, read back once (not timed).
            // Through the product's one read-back path (gpu/texture_readback: the fetch barrier
            // after the evaluation's image stores, the buffer read after the copy pass).
            const std::vector<float> values = gpu::readVolumeTexture(s.texture(), scan.dims());
            std::size_t right = 0;
            std::size_t positive = 0;
            std::size_t negative = 0;
            for (const float value : values) {
                positive += value > 0.0F ? 1 : 0;
                negative += value < 0.0F ? 1 : 0;
            }
            std::fprintf(stderr, "%s: speed > 0 at %zu voxels, < 0 at %zu, = 0 at %zu\n",
                         label.c_str(), positive, negative, values.size() - positive - negative);
            for (std::size_t v = 0; v < values.size(); ++v) {
                right += ((values[v] > 0.0F) == ((*truth)[v] != 0)) ? 1 : 0;
            }
            agreement = static_cast<double>(right) / static_cast<double>(values.size());
            std::size_t both = 0;
            std::size_t sum = 0;
            for (std::size_t v = 0; v < values.size(); ++v) {
                const bool in = values[v] > 0.0F;
                const bool want = (*truth)[v] != 0;
                both += in && want ? 1 : 0;
                sum += (in ? 1 : 0) + (want ? 1 : 0);
            }
            dice = sum > 0 ? 2.0 * static_cast<double>(both) / static_cast<double>(sum) : 1.0;
        }
    }
    auto median = [&](double speed::ClassifierTraining::*field) {
        std::vector<double> v;
        for (const auto& t : runs) {
            v.push_back(t.*field);
        }
        std::sort(v.begin(), v.end());
        return v[v.size() / 2];
    };
    const speed::ClassifierTraining& t = runs.front();
    char agree[48] = "-";
    if (agreement >= 0.0) {
        std::snprintf(agree, sizeof agree, "%.4f (Dice %.3f)", agreement, dice);
    }
    std::printf("| %s | %zu | %.3f | %.3f | %.3f | %.3f | %s |\n", label.c_str(),
                t.insideSamples + t.outsideSamples,
                median(&speed::ClassifierTraining::featureSeconds),
                median(&speed::ClassifierTraining::trainSeconds),
                median(&speed::ClassifierTraining::evaluateSeconds), t.outOfBagAccuracy, agree);
}

} // namespace

int main(int argc, char** argv) {
    try {
        speed::ClassifierParams params;
        params.trees = argOr(argc, argv, "--trees", params.trees);
        params.maxDepth = argOr(argc, argv, "--depth", params.maxDepth);
        params.maxSamplesPerClass = argOr(argc, argv, "--samples", params.maxSamplesPerClass);
        const int size = argOr(argc, argv, "--size", 64);
        const int trainSize = argOr(argc, argv, "--train-size", 256);
        const int repeat = std::max(1, argOr(argc, argv, "--repeat", 3));
        const std::string scanPath = textOr(argc, argv, "--scan", "");
        auto context = platform::createOffscreenContext();
        std::printf(
            "renderer: %s; %d trees, depth <= %d, <= %d samples per class, median of %d\n\n",
            gpu::queryGpuInfo().renderer.c_str(), params.trees, params.maxDepth,
            params.maxSamplesPerClass, repeat);
        std::printf("| scan | samples | features s | training s | evaluation s | out-of-bag "
                    "accuracy | sign = truth |\n|---|---|---|---|---|---|---|\n");
        if (trainSize > 0) {
            timeTraining(phantom(trainSize), params, repeat);
        }
        if (size > 0) {
            const Phantom p = phantom(size);
            const Volume volume = volumeOf(p);
            const gpu::ScanTexture scan(volume);
            timeWhole(scan, volume, std::to_string(size) + "^3 phantom", p.inside, p.outside,
                      params, repeat, &p.truth);
        }
        if (!scanPath.empty()) {
            const Volume volume = bench::loadScan(scanPath);
            const gpu::ScanTexture scan(volume);
            const glm::ivec3 d = scan.dims();
            const std::string truthPath = textOr(argc, argv, "--truth", "");
            std::vector<std::uint8_t> truth;
            if (!truthPath.empty()) {
                const Volume mask = bench::loadScan(truthPath);
                if (mask.dims() != d) {
                    throw std::runtime_error("--truth is not on the scan's grid");
                }
                truth.resize(mask.geometry().voxelCount());
                for (std::size_t v = 0; v < truth.size(); ++v) {
                    truth[v] = mask.storedAt(v) > 0.0 ? 1 : 0;
                }
            }
            timeWhole(scan, volume,
                      std::to_string(d.x) + "x" + std::to_string(d.y) + "x" + std::to_string(d.z) +
                          " " + scanPath.substr(scanPath.find_last_of('/') + 1),
                      examplesOf(argc, argv, "--inside"), examplesOf(argc, argv, "--outside"),
                      params, repeat, truth.empty() ? nullptr : &truth);
        }
    } catch (const std::exception& e) {
        std::fprintf(stderr, "classifier_bench: %s\n", e.what());
        return 1;
    }
    return 0;
}
