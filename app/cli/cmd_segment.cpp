#include "cli/args.hpp"
#include "cli/commands.hpp"
#include "gpu/gpu_info.hpp"
#include "io/mask_writer.hpp"
#include "io/scan_reader.hpp"
#include "platform/egl/gpu_context.hpp"
#include "solver/level_set_solver.hpp"

#include <chrono>
#include <cstdio>
#include <fstream>
#include <nlohmann/json.hpp>
#include <stdexcept>

namespace steerseg::cli {

namespace {

Sphere parseSphere(const std::string& text, const std::string& what) {
    const std::vector<double> v = parseNumberList(text, 4, what);
    return {glm::vec3(static_cast<float>(v[0]), static_cast<float>(v[1]), static_cast<float>(v[2])),
            static_cast<float>(v[3])};
}

// What to run: exactly one of --iterations, --time, --converge.
struct RunMode {
    enum Kind { Iterations, Time, Converge } kind = Iterations;
    int iterations = 0;
    float time = 0.0F;
};

RunMode parseRunMode(const Args& args) {
    const auto iterations = args.integer("iterations");
    const auto time = args.number("time");
    const bool converge = args.flag("converge");
    if (static_cast<int>(iterations.has_value()) + static_cast<int>(time.has_value()) +
            static_cast<int>(converge) !=
        1) {
        throw UsageError("give exactly one of --iterations N, --time t, --converge");
    }
    const auto maxIterations = args.integer("max-iterations");
    if (maxIterations && iterations) {
        throw UsageError("--max-iterations goes with --time or --converge");
    }
    RunMode mode;
    mode.iterations = static_cast<int>(maxIterations.value_or(iterations.value_or(100000)));
    if (mode.iterations < 1 || iterations.value_or(1) > 100000000 ||
        maxIterations.value_or(1) > 100000000) {
        throw UsageError("iteration counts must be between 1 and 100000000");
    }
    if (time) {
        if (*time < 0.0 || *time > 1e7) {
            throw UsageError("--time must be between 0 and 1e7");
        }
        mode.kind = RunMode::Time;
        mode.time = static_cast<float>(*time);
    } else if (converge) {
        mode.kind = RunMode::Converge;
    }
    return mode;
}

} // namespace

int runSegment(std::span<const std::string> words) {
    const Args args(words,
                    {"input", "seed", "erase", "T", "eps", "alpha", "iterations", "time",
                     "max-iterations", "output", "report", "brick-size"},
                    {"converge", "dense"});
    if (!args.positional().empty()) {
        throw UsageError("unexpected argument '" + args.positional().front() + "'");
    }
    const std::string input = args.required("input");
    const std::string output = args.required("output");
    LevelSetParams params;
    params.T = static_cast<float>(parseNumber(args.required("T"), "--T"));
    params.eps = static_cast<float>(parseNumber(args.required("eps"), "--eps"));
    params.alpha = static_cast<float>(parseNumber(args.required("alpha"), "--alpha"));
    try {
        validateParams(params);
    } catch (const std::invalid_argument& e) {
        throw UsageError(e.what());
    }
    std::vector<Sphere> seeds;
    for (const std::string& s : args.values("seed")) {
        seeds.push_back(parseSphere(s, "--seed"));
    }
    std::vector<Sphere> erases;
    for (const std::string& s : args.values("erase")) {
        erases.push_back(parseSphere(s, "--erase"));
    }
    if (seeds.empty()) {
        throw UsageError("give at least one --seed i,j,k,r");
    }
    const RunMode mode = parseRunMode(args);
    SolverOptions options;
    options.dense = args.flag("dense");
    options.brickSize = static_cast<int>(args.integer("brick-size").value_or(0));

    const io::LoadedScan scan = io::readScan(input);
    const Geometry& geometry = scan.volume.geometry();
    for (const Sphere& s : seeds) {
        try {
            validateSphere(s, geometry.dims);
        } catch (const std::invalid_argument& e) {
            throw UsageError(std::string("--seed: ") + e.what());
        }
    }
    for (const Sphere& s : erases) {
        try {
            validateSphere(s, geometry.dims);
        } catch (const std::invalid_argument& e) {
            throw UsageError(std::string("--erase: ") + e.what());
        }
    }

    auto context = platform::createOffscreenContext();
    const std::string renderer = gpu::queryGpuInfo().renderer;
    LevelSetSolver solver(scan.volume, options);
    for (const Sphere& s : seeds) {
        solver.addSphere(s);
    }
    for (const Sphere& s : erases) {
        solver.removeSphere(s);
    }
    solver.setParams(params);

    const auto start = std::chrono::steady_clock::now();
    StepResult result;
    switch (mode.kind) {
    case RunMode::Iterations:
        result = solver.step(mode.iterations);
        break;
    case RunMode::Time:
        result = solver.evolveUntil(mode.time, mode.iterations);
        break;
    case RunMode::Converge:
        result = solver.runUntilConverged(mode.iterations);
        break;
    }
    glFinish();
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();

    const std::vector<std::uint8_t> mask = solver.readMask();
    io::writeMask(output, geometry, mask);

    std::size_t inside = 0;
    for (std::uint8_t m : mask) {
        inside += m;
    }
    const SolverStats stats = solver.stats();
    nlohmann::ordered_json j;
    j["input"] = input;
    j["output"] = output;
    j["T"] = params.T;
    j["eps"] = params.eps;
    j["alpha"] = params.alpha;
    j["mode"] = options.dense ? "dense" : "sparse";
    j["brick_size"] = options.brickSize == 0 ? defaultBrickSize() : options.brickSize;
    j["iterations"] = stats.iterations;
    j["evolved_time"] = stats.evolvedTime;
    j["solve_seconds"] = seconds;
    j["iterations_per_second"] = seconds > 0.0 ? stats.iterations / seconds : 0.0;
    j["converged"] = solver.converged();
    j["inside_voxels"] = inside;
    const double voxelMl = geometry.spacing.x * geometry.spacing.y * geometry.spacing.z / 1000.0;
    j["volume_ml"] = static_cast<double>(inside) * voxelMl;
    j["peak_active_bricks"] = stats.peakActiveBricks;
    j["total_bricks"] = stats.totalBricks;
    j["peak_pool_bytes"] = stats.peakLevelSetBytes;
    j["dense_phi_bytes"] = stats.densePhiBytes;
    j["pool_growths"] = stats.poolGrowths;
    j["pool_shrinks"] = stats.poolShrinks;
    j["renderer"] = renderer;
    (void)result;
    const std::string text = j.dump(2);
    if (const auto report = args.value("report")) {
        std::ofstream out(*report);
        out << text << "\n";
        if (!out) {
            throw std::runtime_error(*report + ": cannot write the report");
        }
    }
    std::printf("%s\n", text.c_str());
    return 0;
}

} // namespace steerseg::cli
