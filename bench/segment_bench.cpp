// Time to a segmentation on a real scan: the solver alone (no session, no renderer), from the
// given seeds and parameters to an evolved time, repeated, with the mask's size and its Dice
// against a reference mask. The GPU half of the ITK comparison (tools/bench-itk.sh gives the
// parameters and ITK's times; this runs where ITK cannot, on the lent GPU machine).
//   segment_bench --scan PATH --seed i,j,k,r [--seed ...] --T v --eps v --alpha a --time t
//                 [--max-iterations N] [--repeat N] [--compare MASK] [--trace N]
//                 [--dense 1] [--brick 4|8|16] [--check N] [--dump-phi FILE]
//                 [--sleep 0|1] [--sleep-tolerance V] [--against-awake 1]
//                 [--converge 1] [--stop-on-leak 1] [--growth-log FILE] [--compare-label N]
//                 [--settle-iterations N] [--settle-displacement V] [--runaway-factor V]
//                 [--voxel-spheres 1]
// Each run prints iterations/s beside the voxels visited per iteration and the front's voxels
// (sleeping bricks, docs/solver.md). --against-awake 1 adds one run with sleeping off and the
// Dice between its mask and the last run's.
// --dump-phi writes phi after the trace as raw float32, i fastest, to diff two runs voxel by
// voxel.
// --converge 1 runs to the solver's own stop (converged, or a leak with --stop-on-leak 1) or
// --max-iterations instead of to --time. --growth-log writes the first run's checks (iteration,
// evolved time, voxels gained, lost, front voxels: solver::FrontCheck), the series the stop
// rules are tested on (tests/data/growth). --compare-label N compares with label N of --compare
// rather than with its non-zero voxels. --settle-iterations 0 turns the settle rule off (the
// convergence rule before it, for comparisons); --runaway-factor 0 the runaway watch.
// --voxel-spheres 1 makes each seed a ball in voxel steps, as ITK's tool seeds it (the product's
// spheres are round in millimetres: model::Sphere), so that the ITK comparison starts both
// solvers from the same voxels.
// --trace N steps one iteration at a time for N iterations and prints the evolved time and a
// checksum of phi after each: two runs of it show where a driver stops being deterministic.
#include "bench/bench_scan.hpp"
#include "gpu/gl.hpp"
#include "gpu/gpu_info.hpp"
#include "platform/egl/offscreen_context.hpp"
#include "solver/level_set_solver.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace {

using namespace steerseg;

struct Options {
    std::string scan;
    std::vector<model::Sphere> seeds;
    model::LevelSetParams params;
    float time = -1.0F;
    int maxIterations = 100000;
    int repeat = 3;
    std::string compare;
    int trace = 0;
    model::SolverOptions solver;
    std::string dumpPhi;
    bool againstAwake = false;
    bool converge = false;
    std::string growthLog;
    int compareLabel = -1;
    bool voxelSpheres = false;
};

model::Sphere parseSeed(const std::string& text) {
    model::Sphere s;
    if (std::sscanf(text.c_str(), "%f,%f,%f,%f", &s.centre.x, &s.centre.y, &s.centre.z,
                    &s.radius) != 4) {
        throw std::invalid_argument("--seed expects i,j,k,r (got '" + text + "')");
    }
    return s;
}

Options parse(int argc, char** argv) {
    Options o;
    for (int n = 1; n + 1 < argc; n += 2) {
        const std::string key = argv[n];
        const std::string value = argv[n + 1];
        if (key == "--scan") {
            o.scan = value;
        } else if (key == "--seed") {
            o.seeds.push_back(parseSeed(value));
        } else if (key == "--T") {
            o.params.T = std::stof(value);
        } else if (key == "--eps") {
            o.params.eps = std::stof(value);
        } else if (key == "--alpha") {
            o.params.alpha = std::stof(value);
        } else if (key == "--time") {
            o.time = std::stof(value);
        } else if (key == "--max-iterations") {
            o.maxIterations = std::max(1, std::stoi(value));
        } else if (key == "--repeat") {
            o.repeat = std::clamp(std::stoi(value), 1, 100);
        } else if (key == "--dense") {
            o.solver.dense = value == "1";
        } else if (key == "--brick") {
            o.solver.brickSize = std::stoi(value);
        } else if (key == "--check") {
            o.solver.checkInterval = std::stoi(value);
        } else if (key == "--sleep") {
            o.solver.sleep = value == "1";
        } else if (key == "--sleep-tolerance") {
            o.solver.sleepTolerance = std::stof(value);
        } else if (key == "--against-awake") {
            o.againstAwake = value == "1";
        } else if (key == "--dump-phi") {
            o.dumpPhi = value;
        } else if (key == "--trace") {
            o.trace = std::clamp(std::stoi(value), 0, 100000);
        } else if (key == "--converge") {
            o.converge = value == "1";
        } else if (key == "--stop-on-leak") {
            o.solver.stopOnLeak = value == "1";
        } else if (key == "--settle-iterations") {
            o.solver.settleIterations = std::stoi(value);
        } else if (key == "--settle-displacement") {
            o.solver.settleDisplacement = std::stof(value);
        } else if (key == "--runaway-factor") {
            o.solver.runawayFactor = std::stof(value);
        } else if (key == "--growth-log") {
            o.growthLog = value;
        } else if (key == "--compare-label") {
            o.compareLabel = std::stoi(value);
        } else if (key == "--voxel-spheres") {
            o.voxelSpheres = value == "1";
        } else if (key == "--compare") {
            o.compare = value;
        } else {
            throw std::invalid_argument("unknown option " + key);
        }
    }
    if (o.scan.empty() || o.seeds.empty() || !(o.time >= 0.0F || o.converge)) {
        throw std::invalid_argument("give --scan, at least one --seed and --time or --converge 1");
    }
    return o;
}

} // namespace

int main(int argc, char** argv) {
    try {
        const Options o = parse(argc, argv);
        Volume volume = bench::loadScan(o.scan);
        if (o.voxelSpheres) {
            // The seeds as balls in voxel steps (ITK's, which knows no spacing here): the PDE is
            // in voxel units either way, so the spacing only shapes the spheres.
            volume.geometry().spacing = glm::dvec3(1.0);
        }
        const Volume reference = o.compare.empty() ? Volume{} : bench::loadScan(o.compare);
        auto context = platform::createOffscreenContext();
        const glm::ivec3 d = volume.dims();
        std::printf("GL_RENDERER: %s\nscan: %s %dx%dx%d\n", gpu::queryGpuInfo().renderer.c_str(),
                    o.scan.c_str(), d.x, d.y, d.z);
        const gpu::ScanTexture texture(volume);
        if (o.trace > 0) {
            solver::LevelSetSolver solver(texture, o.solver);
            for (const model::Sphere& s : o.seeds) {
                solver.addSphere(s);
            }
            solver.setParams(o.params);
            for (int n = 0; n < o.trace; ++n) {
                const model::StepResult r = solver.step(1);
                double sum = 0.0;
                std::size_t inside = 0;
                for (const float v : solver.readPhi()) {
                    sum += static_cast<double>(v);
                    inside += v < 0.0F ? 1 : 0;
                }
                const model::SolverStats st = solver.stats();
                std::printf("trace %d: t %.9g phi-sum %.9g inside %zu active %u capacity %u "
                            "growths %d stalls %d\n",
                            n + 1, static_cast<double>(r.evolvedTime), sum, inside, st.activeBricks,
                            st.capacity, st.poolGrowths, st.stalls);
            }
            if (!o.dumpPhi.empty()) {
                const std::vector<float> phi = solver.readPhi();
                std::ofstream out(o.dumpPhi, std::ios::binary);
                out.write(reinterpret_cast<const char*>(phi.data()),
                          static_cast<std::streamsize>(phi.size() * sizeof(float)));
            }
            return 0;
        }
        std::vector<double> seconds;
        std::vector<std::uint8_t> lastMask;
        const int runs = o.repeat + (o.againstAwake ? 1 : 0);
        for (int run = 0; run < runs; ++run) {
            const bool awakeRun = run == o.repeat;
            model::SolverOptions options = o.solver;
            options.sleep = options.sleep && !awakeRun;
            solver::LevelSetSolver solver(texture, options);
            for (const model::Sphere& s : o.seeds) {
                solver.addSphere(s);
            }
            solver.setParams(o.params);
            std::ofstream log;
            if (run == 0 && !o.growthLog.empty()) {
                log.open(o.growthLog);
                log << "# iteration time gained lost front\n";
                solver.setCheckObserver([&log](const solver::FrontCheck& c) {
                    log << c.iteration << ' ' << c.time << ' ' << c.gained << ' ' << c.lost << ' '
                        << c.front << std::endl; // a long run's series can be watched
                });
            }
            glFinish();
            const auto start = std::chrono::steady_clock::now();
            const model::StepResult r = o.converge ? solver.runUntilConverged(o.maxIterations)
                                                   : solver.evolveUntil(o.time, o.maxIterations);
            glFinish();
            const double elapsed =
                std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
            if (!awakeRun) {
                seconds.push_back(elapsed);
            }
            const std::vector<std::uint8_t> mask = solver.readMask();
            std::size_t inside = 0;
            std::size_t overlap = 0;
            std::size_t referenceInside = 0;
            for (std::size_t n = 0; n < mask.size(); ++n) {
                inside += mask[n];
                if (!o.compare.empty()) {
                    const double label = reference.rescale().apply(reference.storedAt(n));
                    const bool in =
                        o.compareLabel < 0 ? label > 0.5 : std::lround(label) == o.compareLabel;
                    referenceInside += in ? 1 : 0;
                    overlap += (in && mask[n] != 0) ? 1 : 0;
                }
            }
            const model::SolverStats st = solver.stats();
            std::printf("run %d%s: %s, %d iterations, t = %.4f, %.4f s (%.1f it/s), %zu voxels "
                        "inside, %.0f voxels visited per iteration, %u front voxels, %u of %u "
                        "bricks awake at the end",
                        run + 1, awakeRun ? " (sleeping off)" : "",
                        model::stopReasonName(r.stopReason), r.iterations,
                        static_cast<double>(r.evolvedTime), elapsed, r.iterations / elapsed, inside,
                        st.visitedVoxelsPerIteration, st.frontVoxels, st.activeBricks,
                        st.bandBricks);
            if (awakeRun) {
                std::size_t both = 0;
                std::size_t sum = 0;
                for (std::size_t n = 0; n < mask.size(); ++n) {
                    both += (mask[n] != 0 && lastMask[n] != 0) ? 1 : 0;
                    sum += (mask[n] != 0 ? 1 : 0) + (lastMask[n] != 0 ? 1 : 0);
                }
                std::printf(", Dice %.5f against the sleeping run",
                            sum > 0 ? 2.0 * static_cast<double>(both) / static_cast<double>(sum)
                                    : 1.0);
            }
            lastMask = mask;
            if (!o.compare.empty()) {
                std::printf(", Dice %.4f against %s (%zu voxels)",
                            2.0 * static_cast<double>(overlap) /
                                static_cast<double>(inside + referenceInside),
                            o.compare.c_str(), referenceInside);
            }
            std::printf("\n");
        }
        std::sort(seconds.begin(), seconds.end());
        std::printf("median solve seconds: %.4f\n", seconds[seconds.size() / 2]);
        return 0;
    } catch (const std::exception& e) {
        std::fprintf(stderr, "segment_bench: %s\n", e.what());
        return 1;
    }
}
