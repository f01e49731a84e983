// How far each speed's own ingredient can agree with a label when it is fitted to that label
// (docs/speed.md "What the labels allow"): what the accuracy benchmark's figures are read
// against. Not a segmentation and not a test: it looks at the answer.
//   accuracy_bound --scan PATH --label PATH [--label-value N] --seed i,j,k,r [--seed ...]
//                  [--ring R] [--alpha a] [--max-iterations N] [--json FILE]
// - interval: the intensity interval [lo, hi] (lo and hi from the label's own quantiles) whose
//   6-connected region around the seeds agrees best with the label: what a threshold speed
//   holding exactly that interval would fill, before curvature. "anywhere": the same interval
//   without connectivity.
// - classifier: the classification speed's features and forest (the product's own code and
//   defaults), trained on the label's voxels against the voxels within R of it, then its sign at
//   every voxel of that neighbourhood; voxels farther away count as correctly outside.
//   "connected": the positive voxels 6-connected to the seeds.
// - level set: the product's solver on that fitted speed (levelSetBound), which adds what the
//   curvature term's smoothing gains. Curvature can also lift an interval's figure (it cuts
//   thin bridges), so the interval is no strict ceiling for the threshold speed; the level set
//   on the fitted classifier is the figure a goal for the classification speed is read against.
#include "bench/accuracy/voxel_regions.hpp"
#include "bench/bench_scan.hpp"
#include "core/mask_overlap.hpp"
#include "gpu/gl_state_guard.hpp"
#include "gpu/scan_texture.hpp"
#include "platform/egl/offscreen_context.hpp"
#include "solver/level_set_solver.hpp"
#include "speed/classifier_features.hpp"
#include "speed/classifier_features_cpu.hpp"
#include "speed/classifier_speed.hpp"
#include "speed/example_voxels.hpp"
#include "speed/random_forest.hpp"
#include "speed/split_mix.hpp"
#include "speed/volume_texture.hpp"

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <fstream>
#include <stdexcept>
#include <string>
#include <vector>

using namespace steerseg;
using steerseg::bench::connectedToSeeds;
using steerseg::bench::dilated;
using steerseg::bench::Grid;

namespace {

struct Options {
    std::string scan;
    std::string label;
    int labelValue = -1; // -1: every non-zero voxel
    std::vector<speed::Example> seeds;
    int ring = 10;
    int maxIterations = 5000;
    float alpha = 0.5F; // the accuracy benchmark's classify rule
    std::string json;
};

speed::Example parseSphere(const std::string& text) {
    speed::Example e;
    char tail = 0;
    if (std::sscanf(text.c_str(), "%f,%f,%f,%f%c", &e.centre.x, &e.centre.y, &e.centre.z, &e.radius,
                    &tail) != 4 ||
        !(e.radius >= 0.0F)) {
        throw std::runtime_error("--seed wants i,j,k,r, got '" + text + "'");
    }
    return e;
}

Options parse(int argc, char** argv) {
    Options o;
    for (int i = 1; i < argc; ++i) {
        const std::string a = argv[i];
        if (i + 1 >= argc) {
            throw std::runtime_error(a + " needs a value");
        }
        const std::string v = argv[++i];
        if (a == "--scan") {
            o.scan = v;
        } else if (a == "--label") {
            o.label = v;
        } else if (a == "--label-value") {
            o.labelValue = std::stoi(v);
        } else if (a == "--seed") {
            o.seeds.push_back(parseSphere(v));
        } else if (a == "--ring") {
            o.ring = std::stoi(v);
        } else if (a == "--alpha") {
            o.alpha = std::stof(v);
        } else if (a == "--max-iterations") {
            o.maxIterations = std::stoi(v);
        } else if (a == "--json") {
            o.json = v;
        } else {
            throw std::runtime_error("unknown option " + a);
        }
    }
    if (o.scan.empty() || o.label.empty() || o.seeds.empty()) {
        throw std::runtime_error("usage: accuracy_bound --scan PATH --label PATH [--label-value N] "
                                 "--seed i,j,k,r [--seed ...] [--ring R] [--max-iterations N] "
                                 "[--alpha a] [--json FILE]");
    }
    if (!(o.alpha >= 0.0F && o.alpha <= 1.0F)) {
        throw std::runtime_error("--alpha must be in [0, 1]");
    }
    if (o.ring < 1 || o.ring > 64) {
        throw std::runtime_error("--ring must be in [1, 64] voxels");
    }
    return o;
}

double secondsSince(std::chrono::steady_clock::time_point t) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - t).count();
}

struct IntervalBound {
    double lo = 0.0;
    double hi = 0.0;
    double dice = 0.0;         // connected to the seeds
    double diceAnywhere = 0.0; // the same interval, every voxel in it
    std::size_t voxels = 0;
};

IntervalBound intervalBound(const Grid& g, const std::vector<float>& intensity, const Volume& label,
                            int labelValue, const std::vector<std::uint8_t>& inLabel,
                            const std::vector<glm::ivec3>& seedVoxels) {
    std::vector<float> values;
    for (std::size_t v = 0; v < inLabel.size(); ++v) {
        if (inLabel[v] != 0) {
            values.push_back(intensity[v]);
        }
    }
    std::sort(values.begin(), values.end());
    auto quantile = [&](double q) {
        return values[static_cast<std::size_t>(q * static_cast<double>(values.size() - 1))];
    };
    // The label's own tails: a threshold speed's interval is T +- eps, and these bracket every
    // interval that keeps most of the label.
    constexpr std::array kLow{0.005, 0.01, 0.02, 0.05, 0.1, 0.2};
    constexpr std::array kHigh{0.8, 0.9, 0.95, 0.98, 0.99, 0.995};
    IntervalBound best;
    best.dice = -1.0;
    std::vector<std::uint8_t> allowed(g.count());
    for (const double ql : kLow) {
        for (const double qh : kHigh) {
            const float lo = quantile(ql);
            const float hi = quantile(qh);
            for (std::size_t v = 0; v < allowed.size(); ++v) {
                allowed[v] = intensity[v] >= lo && intensity[v] <= hi ? 1 : 0;
            }
            const std::vector<std::uint8_t> region = connectedToSeeds(g, allowed, seedVoxels);
            const MaskOverlap o = maskOverlap(region, label, labelValue);
            if (o.dice() > best.dice) {
                best = {lo, hi, o.dice(), maskOverlap(allowed, label, labelValue).dice(), o.mask};
            }
        }
    }
    return best;
}

struct ClassifierBound {
    std::size_t samples = 0;
    double outOfBag = 0.0;
    double dice = 0.0;          // sign of the speed, every voxel
    double diceConnected = 0.0; // positive voxels connected to the seeds
    double seconds = 0.0;
    // P(inside) - P(outside) at every voxel, -1 beyond the label's neighbourhood.
    std::vector<float> speed;
    std::vector<std::uint8_t> connected; // the positive voxels connected to the seeds
};

ClassifierBound classifierBound(const Grid& g, GLuint intensity, const Volume& label,
                                int labelValue, const std::vector<std::uint8_t>& inLabel,
                                const std::vector<glm::ivec3>& seedVoxels, int ring,
                                glm::ivec3 stride) {
    const auto start = std::chrono::steady_clock::now();
    const std::vector<std::uint8_t> near = dilated(g, inLabel, ring);
    // Every label voxel and every ring voxel, then the product's own cap and reservoir.
    std::vector<glm::ivec3> in;
    std::vector<glm::ivec3> out;
    std::vector<glm::ivec3> all;
    for (std::size_t v = 0; v < near.size(); ++v) {
        if (near[v] != 0) {
            all.push_back(g.at(v));
            (inLabel[v] != 0 ? in : out).push_back(g.at(v));
        }
    }
    if (in.empty() || out.empty()) {
        throw std::runtime_error("the label or its ring is empty");
    }
    const speed::ClassifierParams defaults;
    auto reservoir = [&](std::vector<glm::ivec3> voxels, std::uint64_t seed) {
        const auto cap = static_cast<std::size_t>(defaults.maxSamplesPerClass);
        speed::SplitMix rng(seed);
        for (std::size_t i = cap; i < voxels.size(); ++i) {
            const std::size_t j = rng.below(i + 1);
            if (j < cap) {
                voxels[j] = voxels[i];
            }
        }
        voxels.resize(std::min(cap, voxels.size()));
        return voxels;
    };
    in = reservoir(std::move(in), 1);
    out = reservoir(std::move(out), 2);
    std::vector<glm::ivec3> samples = in;
    samples.insert(samples.end(), out.begin(), out.end());
    std::vector<std::uint8_t> classes(samples.size(), 0);
    std::fill(classes.begin(), classes.begin() + static_cast<std::ptrdiff_t>(in.size()), 1);
    speed::ForestParams forestParams;
    forestParams.trees = defaults.trees;
    forestParams.maxDepth = defaults.maxDepth;
    forestParams.seed = defaults.seed;
    const speed::RandomForest forest =
        speed::RandomForest::train(speed::gatherClassifierFeatures(intensity, g.d, samples, stride),
                                   classes, speed::kClassifierFeatureCount, forestParams);

    // The sign at every voxel of the neighbourhood, in pieces so the feature rows stay small.
    ClassifierBound b;
    b.speed.assign(g.count(), -1.0F);
    std::vector<std::uint8_t> positive(g.count(), 0);
    constexpr std::size_t kPiece = 1U << 20U;
    for (std::size_t first = 0; first < all.size(); first += kPiece) {
        const std::size_t n = std::min(kPiece, all.size() - first);
        const std::span<const glm::ivec3> piece(all.data() + first, n);
        const std::vector<float> f = speed::gatherClassifierFeatures(intensity, g.d, piece, stride);
        for (std::size_t i = 0; i < n; ++i) {
            const std::span<const float> row(f.data() + i * speed::kClassifierFeatureCount,
                                             speed::kClassifierFeatureCount);
            const glm::ivec3 p = piece[i];
            const std::size_t v = linearIndex(g.d, p.x, p.y, p.z);
            b.speed[v] = forest.predict(row);
            positive[v] = b.speed[v] > 0.0F ? 1 : 0;
        }
    }
    b.samples = samples.size();
    b.outOfBag = forest.outOfBagAccuracy();
    b.dice = maskOverlap(positive, label, labelValue).dice();
    b.connected = connectedToSeeds(g, positive, seedVoxels);
    b.diceConnected = maskOverlap(b.connected, label, labelValue).dice();
    b.seconds = secondsSince(start);
    return b;
}

struct LevelSetBound {
    double dice = 0.0;
    std::size_t voxels = 0;
    int iterations = 0;
    std::string stop;
    double seconds = 0.0;
};

// The product's level set with the fitted classifier as its speed, as the accuracy benchmark
// runs the classify speed (alpha 0.5 unless --alpha, to convergence or a leak), started from the
// classifier's
// positive voxels connected to the seeds: what the curvature term's smoothing adds to the
// voxelwise figure. (Started from the seeds alone, a 3-voxel seed shrinks away wherever the
// fitted speed is below the curvature of its sphere, which says nothing about the labels.)
LevelSetBound levelSetBound(const gpu::ScanTexture& scan, const Volume& label, int labelValue,
                            const std::vector<float>& speedField,
                            const std::vector<std::uint8_t>& start, float alpha,
                            int maxIterations) {
    const auto t0 = std::chrono::steady_clock::now();
    const glm::ivec3 d = scan.dims();
    const gpu::Texture field = speed::createVolumeTexture(d, "fitted classifier speed");
    {
        gpu::GlStateGuard guard;
        glBindTexture(GL_TEXTURE_3D, field.id());
        glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
        glTexSubImage3D(GL_TEXTURE_3D, 0, 0, 0, 0, d.x, d.y, d.z, GL_RED, GL_FLOAT,
                        speedField.data());
    }
    model::SolverOptions options;
    options.stopOnLeak = true;
    solver::LevelSetSolver solver(scan, options);
    solver.setParams({0.0F, 0.0F, alpha});
    solver.setSpeedInputs({model::SpeedKind::Classify, 0, field.id(), {}});
    solver.initFromMask(start);
    const model::StepResult r = solver.runUntilConverged(maxIterations);
    const std::vector<std::uint8_t> mask = solver.readMask();
    const MaskOverlap o = maskOverlap(mask, label, labelValue);
    return {o.dice(), o.mask, solver.stats().iterations, model::stopReasonName(r.stopReason),
            secondsSince(t0)};
}

} // namespace

int main(int argc, char** argv) {
    try {
        const Options o = parse(argc, argv);
        const Volume scan = bench::loadScan(o.scan);
        const Volume label = bench::loadScan(o.label);
        const Grid g{scan.dims()};
        if (label.dims() != g.d) {
            throw std::runtime_error("the label is not on the scan's grid");
        }
        const std::vector<std::uint8_t> inLabel = referenceVoxels(label, o.labelValue);
        const auto labelled =
            static_cast<std::size_t>(std::count(inLabel.begin(), inLabel.end(), 1));
        if (labelled == 0) {
            throw std::runtime_error("the label holds no voxel of that value");
        }
        std::vector<glm::ivec3> seedVoxels;
        for (const speed::Example& s : o.seeds) {
            const speed::ExampleVoxels ev =
                speed::exampleVoxels(std::span(&s, 1), g.d, g.count(), 1, "seed");
            seedVoxels.insert(seedVoxels.end(), ev.voxels.begin(), ev.voxels.end());
        }

        const std::vector<float> intensity = scan.realValues();
        const IntervalBound iv =
            intervalBound(g, intensity, label, o.labelValue, inLabel, seedVoxels);
        auto context = platform::createOffscreenContext();
        const gpu::ScanTexture texture(scan);
        const ClassifierBound cb =
            classifierBound(g, texture.exact(), label, o.labelValue, inLabel, seedVoxels, o.ring,
                            speed::classifierFeatureStride(scan.geometry().spacing));

        const LevelSetBound ls = levelSetBound(texture, label, o.labelValue, cb.speed, cb.connected,
                                               o.alpha, o.maxIterations);
        std::printf("label voxels %zu\n", labelled);
        std::printf("interval [%.1f, %.1f]: Dice %.3f connected to the seeds (%zu voxels), %.3f "
                    "anywhere\n",
                    iv.lo, iv.hi, iv.dice, iv.voxels, iv.diceAnywhere);
        std::printf("classifier fitted on the label (ring %d, %zu samples, out-of-bag %.3f): Dice "
                    "%.3f, %.3f connected to the seeds (%.1f s)\n",
                    o.ring, cb.samples, cb.outOfBag, cb.dice, cb.diceConnected, cb.seconds);
        std::printf("level set on the fitted classifier (alpha %.2f): Dice %.3f (%zu voxels, %s "
                    "after %d iterations, %.1f s)\n",
                    static_cast<double>(o.alpha), ls.dice, ls.voxels, ls.stop.c_str(),
                    ls.iterations, ls.seconds);
        if (!o.json.empty()) {
            std::ofstream j(o.json);
            j << "{\"label_voxels\": " << labelled << ", \"interval\": {\"lo\": " << iv.lo
              << ", \"hi\": " << iv.hi << ", \"dice\": " << iv.dice
              << ", \"dice_anywhere\": " << iv.diceAnywhere << ", \"voxels\": " << iv.voxels
              << "}, \"classifier\": {\"ring\": " << o.ring << ", \"samples\": " << cb.samples
              << ", \"out_of_bag\": " << cb.outOfBag << ", \"dice\": " << cb.dice
              << ", \"dice_connected\": " << cb.diceConnected
              << "}, \"level_set\": {\"alpha\": " << o.alpha << ", \"dice\": " << ls.dice
              << ", \"voxels\": " << ls.voxels << ", \"iterations\": " << ls.iterations
              << ", \"stop\": \"" << ls.stop << "\"}}\n";
            if (!j) {
                throw std::runtime_error("cannot write " + o.json);
            }
        }
    } catch (const std::exception& e) {
        std::fprintf(stderr, "accuracy_bound: %s\n", e.what());
        return 1;
    }
    return 0;
}
