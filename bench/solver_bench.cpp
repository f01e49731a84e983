// Sparse packed-brick solver benchmark: iterations/s and level-set bytes against the number of
// active bricks, sparse against dense (same kernels, every brick active) at several active
// fractions, and brick sizes 4 / 8 / 16. Prints markdown tables. Not a test: numbers depend on
// the machine (llvmpipe on a shared 2-core box is noisy; run it alone). The per-pass tables run
// with sleeping off (every brick of the band does its full work); the last table runs a front
// that has stopped with sleeping on and off (voxels visited per iteration beside iterations/s).
// --readback WxHxD times reading the level set back as a mask (the kiosk's autosave, exports) on
// a grid of that size, against the dense phi and its sign, in the same run.
// --small-front-only 1 prints the GL-calls table alone (issue 50's small front), for timing it
// against another build in alternation within the same minutes.
//   solver_bench [--size N] [--iterations N] [--dense-size N] [--readback WxHxD]
//                [--small-front-only 1]
#include "gpu/gl_counts.hpp"
#include "gpu/gpu_info.hpp"
#include "platform/egl/offscreen_context.hpp"
#include "solver/level_set_solver.hpp"
#include "solver/phi_init.hpp"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

using namespace steerseg;

namespace {

struct Measurement {
    double iterationsPerSecond = 0.0;
    model::SolverStats stats;
    gpu::GlCounts calls; // over the timed steps (gpu/gl_counts)
    int iterations = 0;
};

// `iterations` steps timed with the GPU's work finished on both sides; the rate and the stats.
Measurement timedSteps(solver::LevelSetSolver& solver, int iterations) {
    glFinish();
    const auto start = std::chrono::steady_clock::now();
    const gpu::GlCounts before = gpu::glCounts();
    const model::StepResult r = solver.step(iterations);
    const gpu::GlCounts calls = gpu::glCounts() - before;
    glFinish();
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return {r.iterations / seconds, solver.stats(), calls, r.iterations};
}

// A static-ish workload: a sphere of radius r under a zero data speed (T = intensity) and a
// little curvature, so the active set stays the same while every pass does its full work.
Measurement measure(int size, float radius, const model::SolverOptions& options, int iterations) {
    const glm::ivec3 d(size);
    const std::vector<float> volume(static_cast<std::size_t>(size) * size * size, 100.0F);
    solver::LevelSetSolver solver(volume, d, options);
    solver.addSphere({glm::vec3(static_cast<float>(size) / 2.0F), radius});
    solver.setParams({100.0F, 0.0F, 0.9F});
    solver.step(options.checkInterval); // warm-up: programs, pool growth
    return timedSteps(solver, iterations);
}

// A front that has stopped: a seed fills a ball (speed +40 inside, -40 outside) within the
// warm-up, then `iterations` are timed while the surface rests at the ball's edge.
Measurement measureStopped(int size, bool sleep, int iterations) {
    const glm::ivec3 d(size);
    const float radius = static_cast<float>(size) / 4.0F;
    const glm::vec3 centre(static_cast<float>(size) / 2.0F);
    std::vector<float> volume(static_cast<std::size_t>(size) * size * size, 0.0F);
    for (int k = 0; k < size; ++k) {
        for (int j = 0; j < size; ++j) {
            for (int i = 0; i < size; ++i) {
                if (glm::length(glm::vec3(i, j, k) - centre) <= radius) {
                    volume[static_cast<std::size_t>(i + size * (j + size * k))] = 100.0F;
                }
            }
        }
    }
    model::SolverOptions options;
    options.sleep = sleep;
    solver::LevelSetSolver solver(volume, d, options);
    solver.addSphere({centre, 3.0F});
    solver.setParams({100.0F, 50.0F, 0.8F});
    solver.step(8 * size); // the fill: ~0.5 voxel per iteration
    const model::SolverStats before = solver.stats();
    Measurement m = timedSteps(solver, iterations);
    // Over the timed iterations only.
    m.stats.visitedVoxelsPerIteration =
        static_cast<double>(m.stats.visitedVoxels - before.visitedVoxels) /
        (m.stats.iterations - before.iterations);
    return m;
}

double mib(std::size_t bytes) {
    return static_cast<double>(bytes) / (1024.0 * 1024.0);
}

int argOr(int argc, char** argv, const std::string& name, int fallback) {
    for (int i = 1; i + 1 < argc; ++i) {
        if (argv[i] == name) {
            return std::atoi(argv[i + 1]);
        }
    }
    return fallback;
}

// The mask read straight from the bricks (LevelSetSolver::readMask) against the dense phi and its
// sign, on a sphere of a sixth of the grid's smallest side grown a check interval: median of 3.
void timeReadback(const glm::ivec3& d) {
    const std::vector<float> volume(static_cast<std::size_t>(d.x) * d.y * d.z, 100.0F);
    solver::LevelSetSolver s(volume, d);
    s.addSphere({glm::vec3(d) / 2.0F, static_cast<float>(std::min({d.x, d.y, d.z})) / 6.0F});
    s.setParams({100.0F, 10.0F, 0.8F});
    s.step(model::SolverOptions{}.checkInterval);
    std::vector<double> dense;
    std::vector<double> bricks;
    bool same = true;
    for (int r = 0; r < 3; ++r) {
        auto t = std::chrono::steady_clock::now();
        const std::vector<std::uint8_t> a = solver::insideMask(s.readPhi());
        dense.push_back(
            std::chrono::duration<double>(std::chrono::steady_clock::now() - t).count());
        t = std::chrono::steady_clock::now();
        const std::vector<std::uint8_t> b = s.readMask();
        bricks.push_back(
            std::chrono::duration<double>(std::chrono::steady_clock::now() - t).count());
        same = same && a == b;
    }
    std::sort(dense.begin(), dense.end());
    std::sort(bricks.begin(), bricks.end());
    std::printf(
        "\n## The mask read back, %dx%dx%d\n\n| dense phi, then its sign (ms) | from the "
        "bricks (ms) | ratio | same mask |\n|---|---|---|---|\n| %.1f | %.1f | %.1fx | %s |\n",
        d.x, d.y, d.z, 1e3 * dense[1], 1e3 * bricks[1], dense[1] / bricks[1], same ? "yes" : "NO");
}

} // namespace

int main(int argc, char** argv) {
    const int size = argOr(argc, argv, "--size", 128);
    const int iterations = argOr(argc, argv, "--iterations", 32);
    const int denseSize = argOr(argc, argv, "--dense-size", 256);
    const bool smallFrontOnly = argOr(argc, argv, "--small-front-only", 0) != 0;
    auto context = platform::createOffscreenContext();
    std::printf("renderer: %s, volume %d^3, %d timed iterations each\n\n",
                gpu::queryGpuInfo().renderer.c_str(), size, iterations);

    std::printf("## Brick size (sphere r = %d, sparse)\n\n", size / 4);
    std::printf("| brick | active bricks | active voxels | iterations/s | voxel-updates/s (M) |\n");
    std::printf("|---|---|---|---|---|\n");
    for (const int b : {4, 8, 16}) {
        if (smallFrontOnly) {
            break;
        }
        model::SolverOptions o;
        o.brickSize = b;
        o.sleep = false;
        const Measurement m = measure(size, static_cast<float>(size) / 4.0F, o, iterations);
        const double voxels = static_cast<double>(m.stats.activeBricks) * b * b * b;
        std::printf("| %d | %u | %.0f | %.1f | %.1f |\n", b, m.stats.activeBricks, voxels,
                    m.iterationsPerSecond, voxels * m.iterationsPerSecond / 1e6);
    }

    {
        // What an iteration costs whatever the GPU (issue 50): its passes, not its work.
        const Measurement m = measure(size, static_cast<float>(size) / 16.0F, {}, iterations);
        const auto per = [&](std::uint64_t n) {
            return static_cast<double>(n) / static_cast<double>(std::max(m.iterations, 1));
        };
        std::printf("\n## GL calls per iteration, small front (sphere r = %d, sleeping on)\n\n",
                    size / 16);
        std::printf("| active bricks | iterations/s | dispatches | memory barriers | host syncs "
                    "(read-backs + glFinish) |\n|---|---|---|---|---|\n");
        std::printf("| %u | %.1f | %.2f | %.2f | %.3f |\n", m.stats.activeBricks,
                    m.iterationsPerSecond, per(m.calls.dispatches), per(m.calls.barriers),
                    per(m.calls.hostSyncs()));
    }
    if (smallFrontOnly) {
        return 0;
    }

    std::printf("\n## Sparse vs dense (brick %d)\n\n", model::defaultBrickSize());
    std::printf("| sphere r | active bricks | active %% | sparse it/s | dense it/s | speed-up | "
                "level-set MiB | active bricks' MiB + page table | ratio | dense phi MiB |\n");
    std::printf("|---|---|---|---|---|---|---|---|---|---|\n");
    model::SolverOptions denseOptions;
    denseOptions.dense = true;
    const Measurement dense =
        measure(size, static_cast<float>(size) / 8.0F, denseOptions, iterations);
    model::SolverOptions awake;
    awake.sleep = false;
    for (const float fraction : {0.06F, 0.12F, 0.25F, 0.4F}) {
        const float r = fraction * static_cast<float>(size);
        const Measurement m = measure(size, r, awake, iterations);
        const std::size_t brickBytes = static_cast<std::size_t>(model::defaultBrickSize()) *
                                       model::defaultBrickSize() * model::defaultBrickSize() * 4;
        const std::size_t activeBytes =
            m.stats.activeBricks * brickBytes + static_cast<std::size_t>(m.stats.totalBricks) * 4;
        std::printf("| %.0f | %u | %.1f | %.1f | %.2f | %.1fx | %.2f | %.2f | %.2f | %.1f |\n",
                    static_cast<double>(r), m.stats.activeBricks,
                    100.0 * m.stats.activeBricks / m.stats.totalBricks, m.iterationsPerSecond,
                    dense.iterationsPerSecond, m.iterationsPerSecond / dense.iterationsPerSecond,
                    mib(m.stats.levelSetBytes), mib(activeBytes),
                    static_cast<double>(m.stats.levelSetBytes) / static_cast<double>(activeBytes),
                    mib(m.stats.densePhiBytes));
    }

    std::printf("\n## A stopped front, sleeping bricks off and on (ball r = %d)\n\n", size / 4);
    std::printf("| sleeping | iterations/s | voxels visited per iteration | front voxels | awake / "
                "stored bricks |\n|---|---|---|---|---|\n");
    for (const bool sleep : {false, true}) {
        const Measurement m = measureStopped(size, sleep, iterations);
        std::printf("| %s | %.1f | %.0f | %u | %u / %u |\n", sleep ? "on" : "off",
                    m.iterationsPerSecond, m.stats.visitedVoxelsPerIteration, m.stats.frontVoxels,
                    m.stats.activeBricks, m.stats.bandBricks);
    }

    if (denseSize > 0) {
        const Measurement big =
            measure(denseSize, static_cast<float>(denseSize) / 4.0F, denseOptions, 4);
        std::printf("\nDense mode at %d^3: %.2f iterations/s, level set %.1f MiB (%u bricks)\n",
                    denseSize, big.iterationsPerSecond, mib(big.stats.levelSetBytes),
                    big.stats.activeBricks);
    }
    for (int i = 1; i + 1 < argc; ++i) {
        glm::ivec3 d(0);
        if (std::string(argv[i]) == "--readback" &&
            std::sscanf(argv[i + 1], "%dx%dx%d", &d.x, &d.y, &d.z) == 3 && d.x > 0 && d.y > 0 &&
            d.z > 0) {
            timeReadback(d);
        }
    }
    return 0;
}
