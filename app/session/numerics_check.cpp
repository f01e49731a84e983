#include "session/numerics_check.hpp"

#include "core/mask_overlap.hpp"
#include "core/volume.hpp"
#include "gpu/gl_error.hpp"
#include "gpu/gl_state_guard.hpp"
#include "gpu/scan_texture.hpp"
#include "gpu/texture_readback.hpp"
#include "model/level_set_params.hpp"
#include "solver/level_set_solver.hpp"
#include "solver/phi_stencil.hpp"
#include "solver/reference_solver.hpp"
#include "speed/classifier_features.hpp"
#include "speed/classifier_speed.hpp"
#include "speed/classifier_speed_cpu.hpp"
#include "speed/edge_factor.hpp"
#include "speed/preprocess_cpu.hpp"
#include "speed/smoothing.hpp"
#include "speed/speed_values.hpp"
#include "speed/split_mix.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <exception>
#include <functional>
#include <limits>
#include <memory>
#include <span>

namespace steerseg::session {

namespace {

using model::SpeedKind;

// A rough-textured ball in calm tissue of the same mean beside a bright calm slab (the
// classifier benchmark's phantom, small): no threshold on the intensity separates the ball, so
// a classifier that learnt the wrong rows (the H100's fault) calls the calm tissue inside. Odd
// and even sides, so that a fault tied to a multiple of a work group's size shows.
constexpr glm::ivec3 kDims{33, 28, 23};
const glm::vec3 kBall{13.0F, 14.0F, 11.0F};
constexpr float kBallRadius = 7.0F;
constexpr int kIterations = 12;
const model::LevelSetParams kParams{100.0F, 30.0F, 0.7F};

Volume phantom() {
    Geometry g;
    g.dims = kDims;
    Volume v(VoxelType::Float32, g);
    speed::SplitMix rng(47);
    std::span<float> out = v.voxels<float>();
    std::size_t n = 0;
    for (int k = 0; k < kDims.z; ++k) {
        for (int j = 0; j < kDims.y; ++j) {
            for (int i = 0; i < kDims.x; ++i, ++n) {
                const auto u =
                    static_cast<float>(static_cast<double>(rng.next() >> 11U) * 0x1.0p-52 - 1.0);
                const bool ball = glm::length(glm::vec3(i, j, k) - kBall) <= kBallRadius;
                out[n] = ball ? 100.0F + 40.0F * u : (i > 25 ? 160.0F : 100.0F) + 8.0F * u;
            }
        }
    }
    v.invalidateStats();
    return v;
}

std::vector<glm::ivec3> allVoxels() {
    std::vector<glm::ivec3> out;
    out.reserve(static_cast<std::size_t>(kDims.x) * kDims.y * kDims.z);
    for (int k = 0; k < kDims.z; ++k) {
        for (int j = 0; j < kDims.y; ++j) {
            for (int i = 0; i < kDims.x; ++i) {
                out.emplace_back(i, j, k);
            }
        }
    }
    return out;
}

// How far the GPU's values lie from the CPU's: the largest difference, and how many lie beyond
// a tolerance of absolute + relative * |cpu| (a value that is not a number lies beyond any).
struct Gap {
    double largest = 0.0;
    std::size_t beyond = 0;
    std::size_t count = 0;
};

Gap gapOf(std::span<const float> gpu, std::span<const float> cpu, double absolute,
          double relative) {
    Gap g;
    g.count = cpu.size();
    if (gpu.size() != cpu.size()) {
        g.largest = std::numeric_limits<double>::infinity();
        g.beyond = g.count;
        return g;
    }
    for (std::size_t n = 0; n < cpu.size(); ++n) {
        const double d = std::abs(static_cast<double>(gpu[n]) - static_cast<double>(cpu[n]));
        const bool finite = std::isfinite(d);
        g.largest = std::max(g.largest, finite ? d : std::numeric_limits<double>::infinity());
        g.beyond +=
            !finite || d > absolute + relative * std::abs(static_cast<double>(cpu[n])) ? 1 : 0;
    }
    return g;
}

std::string number(double x) {
    char text[32];
    std::snprintf(text, sizeof text, "%.3g", x);
    return text;
}

// One comparison's verdict for a speed: passes while no more than `allowed` values lie beyond
// the tolerance.
struct Verdict {
    SpeedNumerics& out;
    void compare(const std::string& what, const Gap& gap, std::size_t allowed = 0) {
        out.largestDifference = std::max(out.largestDifference, gap.largest);
        std::string line = what + " within " + number(gap.largest);
        if (gap.beyond > allowed) {
            fail(line + " (" + std::to_string(gap.beyond) + " of " + std::to_string(gap.count) +
                 " beyond tolerance)");
        } else {
            note(line);
        }
    }
    void note(const std::string& line) { out.detail += (out.detail.empty() ? "" : "; ") + line; }
    void fail(const std::string& why) {
        out.passed = false;
        note(why);
        out.failure += (out.failure.empty() ? "" : "; ") + why;
    }
};

// kIterations of the GPU solver and of the dense reference from the same seed: the same front
// (the solver agreement tests' rule: no label differs off the surface, the evolved time within
// 1e-3). The reference reads the intensities and factor the GPU's speed read, read back, so
// that this compares the solver alone.
void compareSolver(Verdict& v, solver::LevelSetSolver& gpu, const speed::SpeedInputs& inputs,
                   std::vector<float> intensities, std::vector<float> factor) {
    const model::Sphere seed{kBall, 3.0F};
    gpu.initFromMask(std::vector<std::uint8_t>(intensities.size(), 0));
    gpu.setSpeedInputs(inputs);
    gpu.setParams(kParams);
    gpu.addSphere(seed);
    // The solver's evolved time counts from its first step, whatever the level set since.
    const float before = gpu.stats().evolvedTime;
    const model::StepResult r = gpu.step(kIterations);
    solver::ReferenceSolver cpu(std::move(intensities), kDims);
    if (inputs.kind != SpeedKind::Threshold) {
        cpu.setSpeed(inputs.kind, std::move(factor), inputs.withinWindow);
    }
    cpu.setParams(kParams);
    cpu.addSphere(seed);
    cpu.step(kIterations);
    const std::size_t off = differencesOffSurface(kDims, gpu.readMask(), cpu.mask());
    const double time = std::abs(static_cast<double>(r.evolvedTime - before - cpu.evolvedTime()));
    std::string line = std::to_string(kIterations) + " solver iterations: " + std::to_string(off) +
                       " voxels apart off the surface, evolved time within " + number(time);
    if (off > 0 || !(time <= 1e-3 * static_cast<double>(cpu.evolvedTime())) ||
        r.iterations != kIterations) {
        v.fail(line + " (not the reference's front)");
    } else {
        v.note(line);
    }
}

// The data term the solver reads, on the GPU, against solver::dataSpeed over the same inputs.
void compareSpeed(Verdict& v, const speed::SpeedInputs& inputs, GLuint rawScan,
                  std::span<const float> intensities, std::span<const float> factor) {
    const gpu::Texture values = speed::speedValues(inputs, rawScan, kDims, kParams);
    const std::vector<float> gpu = gpu::readVolumeTexture(values.id(), kDims);
    std::vector<float> cpu(intensities.size());
    for (std::size_t n = 0; n < cpu.size(); ++n) {
        cpu[n] = solver::dataSpeed(intensities[n], factor.empty() ? 0.0F : factor[n], inputs.kind,
                                   kParams, inputs.withinWindow);
    }
    v.compare("speed at " + std::to_string(cpu.size()) + " voxels", gapOf(gpu, cpu, 1e-4, 1e-5));
}

void checkThreshold(Verdict& v, const gpu::ScanTexture& scan, solver::LevelSetSolver& solver,
                    const std::vector<float>& intensities) {
    const speed::SpeedInputs inputs{};
    compareSpeed(v, inputs, scan.exact(), intensities, {});
    compareSolver(v, solver, inputs, intensities, {});
}

void checkEdge(Verdict& v, const gpu::ScanTexture& scan, solver::LevelSetSolver& solver,
               const std::vector<float>& intensities) {
    const speed::SmoothingParams smoothing{2, 24.0F};
    const float kappa = 8.0F;
    const gpu::Texture smoothed = speed::smoothScan(scan.exact(), kDims, smoothing);
    const gpu::Texture factor = speed::edgeFactor(smoothed.id(), kDims, kappa);
    const std::vector<float> gpuSmoothed = gpu::readVolumeTexture(smoothed.id(), kDims);
    const std::vector<float> gpuFactor = gpu::readVolumeTexture(factor.id(), kDims);
    const std::vector<float> cpuSmoothed = speed::cpuSmoothScan(intensities, kDims, smoothing);
    v.compare("smoothed scan", gapOf(gpuSmoothed, cpuSmoothed, 1e-3, 1e-5));
    v.compare("edge factor",
              gapOf(gpuFactor, speed::cpuEdgeFactor(gpuSmoothed, kDims, kappa), 1e-4, 0.0));
    const speed::SpeedInputs inputs{SpeedKind::Edge, smoothed.id(), factor.id(), {}, false};
    compareSpeed(v, inputs, scan.exact(), gpuSmoothed, gpuFactor);
    compareSolver(v, solver, inputs, gpuSmoothed, gpuFactor);
}

void checkClassify(Verdict& v, const Volume& volume, const gpu::ScanTexture& scan,
                   solver::LevelSetSolver& solver, const std::vector<float>& intensities) {
    const std::vector<glm::ivec3> voxels = allVoxels();
    const std::vector<float> cpuFeatures = speed::cpuClassifierFeatures(intensities, kDims, voxels);
    try {
        v.compare("gathered features",
                  gapOf(speed::gatherClassifierFeatures(scan.exact(), kDims, voxels), cpuFeatures,
                        1e-3, 1e-5));
    } catch (const gpu::GpuNumericsError& e) {
        v.fail(e.what());
    }
    // A fine series' windows step more than a voxel (speed::classifierFeatureStride).
    const glm::ivec3 stride{2, 2, 1};
    try {
        v.compare("gathered features, windows stepping 2 x 2 x 1 voxels",
                  gapOf(speed::gatherClassifierFeatures(scan.exact(), kDims, voxels, stride),
                        speed::cpuClassifierFeatures(intensities, kDims, voxels, stride), 1e-3,
                        1e-5));
    } catch (const gpu::GpuNumericsError& e) {
        v.fail(e.what());
    }
    const std::vector<speed::Example> inside{{kBall, 3.0F}};
    const std::vector<speed::Example> outside{{glm::vec3(13.0F, 14.0F, 20.0F), 2.5F},
                                              {glm::vec3(29.0F, 14.0F, 11.0F), 2.5F}};
    speed::ClassifierParams params;
    params.evaluation = speed::ClassifierEvaluation::OnDemand; // the console's
    params.trees = 16;
    const speed::ClassifierSpeed classifier(scan.exact(), kDims, inside, outside, params, {},
                                            &volume);
    // The forest's walk alone, on the CPU's features: beside the evaluation below, which computes
    // its features itself, it tells a GPU that walks the trees wrongly from one that computes the
    // features wrongly (both agree on the CPU's floats, so the walk takes the same branches).
    try {
        v.compare("forest walk on the CPU's features",
                  gapOf(classifier.walkOnGpu(cpuFeatures),
                        speed::cpuForestLooks(classifier.forest(), cpuFeatures), 1e-5, 0.0));
    } catch (const gpu::GpuNumericsError& e) {
        v.fail(e.what());
    }
    // The solver's own evaluation of the bricks (solver/evaluate_speed.comp), over every brick.
    speed::SpeedInputs inputs{SpeedKind::Classify, 0, classifier.texture(),
                              classifier.onDemandForest(), true};
    solver.setSpeedInputs(inputs);
    for (int n = 0; n < 64 && solver.evaluateSpeedAhead(1U << 20U) > 0; ++n) {
    }
    const std::vector<float> gpuFactor = gpu::readVolumeTexture(classifier.texture(), kDims);
    // The marks' vote is a half float, filtered (0.01 at most); a voxel whose feature lies within
    // a rounding of a split's threshold may take the other branch of a tree: a few in a thousand.
    v.compare("evaluation",
              gapOf(gpuFactor,
                    speed::cpuClassifierSpeed(classifier.forest(), classifier.placeVote(),
                                              cpuFeatures, voxels),
                    0.02, 0.0),
              voxels.size() / 500);
    const speed::SpeedInputs complete{SpeedKind::Classify, 0, classifier.texture(), {}, true};
    compareSpeed(v, complete, scan.exact(), intensities, gpuFactor);
    compareSolver(v, solver, inputs, intensities, gpuFactor);
}

} // namespace

bool NumericsReport::passed(SpeedKind kind) const {
    return std::any_of(speeds.begin(), speeds.end(),
                       [&](const SpeedNumerics& s) { return s.kind == kind && s.passed; });
}

bool NumericsReport::allPassed() const {
    return std::all_of(speeds.begin(), speeds.end(),
                       [](const SpeedNumerics& s) { return s.passed; });
}

NumericsReport checkGpuNumerics() {
    const auto start = std::chrono::steady_clock::now();
    NumericsReport report;
    gpu::GlStateGuard guard;
    const Volume volume = phantom();
    const std::vector<float> intensities = volume.realValues();
    std::unique_ptr<gpu::ScanTexture> scan;
    std::unique_ptr<solver::LevelSetSolver> solver;
    std::string setUp;
    try {
        scan = std::make_unique<gpu::ScanTexture>(volume);
        solver = std::make_unique<solver::LevelSetSolver>(*scan);
    } catch (const std::exception& e) {
        setUp = std::string("the check could not start: ") + e.what();
    }
    using Check = std::function<void(Verdict&)>;
    const std::pair<SpeedKind, Check> checks[] = {
        {SpeedKind::Threshold, [&](Verdict& v) { checkThreshold(v, *scan, *solver, intensities); }},
        {SpeedKind::Edge, [&](Verdict& v) { checkEdge(v, *scan, *solver, intensities); }},
        {SpeedKind::Classify,
         [&](Verdict& v) { checkClassify(v, volume, *scan, *solver, intensities); }},
    };
    for (const auto& [kind, check] : checks) {
        SpeedNumerics s{kind, true, 0.0, "", ""};
        Verdict v{s};
        if (!setUp.empty()) {
            v.fail(setUp);
        } else {
            try {
                check(v);
            } catch (const std::exception& e) {
                v.fail(e.what());
            }
        }
        report.speeds.push_back(std::move(s));
    }
    report.seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return report;
}

} // namespace steerseg::session
