#include "cli/args.hpp"
#include "cli/commands.hpp"
#include "cli/segmentation_options.hpp"
#include "gpu/gpu_info.hpp"
#include "io/mask_writer.hpp"
#include "io/scan_reader.hpp"
#include "platform/egl/gpu_context.hpp"
#include "solver/level_set_solver.hpp"

#include <cstdio>
#include <fstream>
#include <nlohmann/json.hpp>
#include <stdexcept>

namespace steerseg::cli {

int runSegment(std::span<const std::string> words) {
    std::vector<std::string> valueOptions = segmentationValueOptions();
    valueOptions.insert(valueOptions.end(), {"input", "output", "report"});
    const Args args(words, valueOptions, segmentationFlagOptions());
    if (!args.positional().empty()) {
        throw UsageError("unexpected argument '" + args.positional().front() + "'");
    }
    const std::string input = args.required("input");
    const std::string output = args.required("output");
    const SegmentationRequest request = parseSegmentation(args);

    const io::LoadedScan scan = io::readScan(input);
    const Geometry& geometry = scan.volume.geometry();
    checkSpheresInside(request, geometry.dims);

    auto context = platform::createOffscreenContext();
    const std::string renderer = gpu::queryGpuInfo().renderer;
    LevelSetSolver solver(scan.volume, request.options);
    const SegmentationRun run = runSegmentation(solver, request);
    const double seconds = run.solveSeconds;
    const LevelSetParams& params = request.params;
    const SolverOptions& options = request.options;

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
    j["stop_reason"] = stopReasonName(run.result.stopReason);
    j["inside_voxels"] = inside;
    const double voxelMl = geometry.spacing.x * geometry.spacing.y * geometry.spacing.z / 1000.0;
    j["volume_ml"] = static_cast<double>(inside) * voxelMl;
    j["peak_active_bricks"] = stats.peakActiveBricks;
    j["total_bricks"] = stats.totalBricks;
    j["peak_pool_bytes"] = stats.peakLevelSetBytes;
    // At the end: the still band's storage, against the peak taken while it grew.
    j["active_bricks"] = stats.activeBricks;
    j["pool_bytes"] = stats.levelSetBytes;
    j["dense_phi_bytes"] = stats.densePhiBytes;
    j["pool_growths"] = stats.poolGrowths;
    j["pool_shrinks"] = stats.poolShrinks;
    j["renderer"] = renderer;
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
