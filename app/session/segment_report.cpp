#include "session/segment_report.hpp"

#include <algorithm>
#include <nlohmann/json.hpp>

namespace steerseg::session {

bool surfaceVanished(std::span<const std::uint8_t> mask) {
    return std::none_of(mask.begin(), mask.end(), [](std::uint8_t m) { return m != 0; });
}

std::string segmentReport(const Session& session, const RunOutcome& run,
                          std::span<const std::uint8_t> mask, const ReportContext& context) {
    const Geometry& geometry = session.scan().geometry();
    const model::LevelSetParams& params = context.params;
    const model::SolverOptions& options = session.options();
    const double seconds = run.solveSeconds;
    std::size_t inside = 0;
    for (const std::uint8_t m : mask) {
        inside += m;
    }
    const model::SolverStats stats = session.stats();
    nlohmann::ordered_json j;
    j["input"] = context.input;
    j["output"] = context.output;
    j["T"] = params.T;
    j["eps"] = params.eps;
    j["alpha"] = params.alpha;
    const SpeedSettings& speed = session.speed();
    nlohmann::ordered_json sp;
    sp["name"] = std::string(model::speedKindName(speed.kind));
    sp["smoothing_iterations"] = speed.smoothing.iterations;
    sp["conductance"] = speed.smoothing.conductance;
    if (speed.kind == model::SpeedKind::Edge) {
        sp["kappa"] = speed.kappa;
    }
    if (speed.kind == model::SpeedKind::Classify) {
        sp["inside_examples"] = speed.inside.size();
        sp["outside_examples"] = speed.outside.size();
        sp["within_window"] = speed.withinWindow;
        sp["place_reach"] = speed.placeReach;
    }
    j["speed"] = sp;
    j["preprocessing_seconds"] = session.speedTiming().preprocessingSeconds;
    j["training_seconds"] = session.speedTiming().trainingSeconds;
    if (speed.kind == model::SpeedKind::Classify) {
        // Evaluated where the front went: its share of the scan is the saving (docs/speed.md).
        j["speed_bricks_evaluated"] = session.speedBricksEvaluated();
    }
    j["mode"] = options.dense ? "dense" : "sparse";
    j["brick_size"] = options.brickSize == 0 ? model::defaultBrickSize() : options.brickSize;
    j["iterations"] = stats.iterations;
    j["evolved_time"] = stats.evolvedTime;
    j["solve_seconds"] = seconds;
    j["iterations_per_second"] = seconds > 0.0 ? stats.iterations / seconds : 0.0;
    // The cost per iteration against the work it must do (sleeping bricks, docs/solver.md).
    j["sleep"] = options.sleep;
    j["voxels_visited_per_iteration"] = stats.visitedVoxelsPerIteration;
    j["front_voxels"] = stats.frontVoxels;
    j["band_bricks"] = stats.bandBricks;
    // What an iteration costs whatever the GPU: its passes, their barriers and the host's waits
    // (issue 50); the run's own, so per iteration of this call.
    const RunCalls& calls = run.calls;
    const double perIteration =
        run.result.iterations > 0 ? 1.0 / static_cast<double>(run.result.iterations) : 0.0;
    j["gl_calls"] = {{"dispatches", calls.dispatches},
                     {"memory_barriers", calls.barriers},
                     {"read_backs", calls.readBacks},
                     {"finishes", calls.finishes}};
    j["dispatches_per_iteration"] = static_cast<double>(calls.dispatches) * perIteration;
    j["barriers_per_iteration"] = static_cast<double>(calls.barriers) * perIteration;
    j["host_syncs_per_iteration"] =
        static_cast<double>(calls.readBacks + calls.finishes) * perIteration;
    // It answered nothing: the report says so rather than "converged" with no voxel inside.
    const bool vanished = surfaceVanished(mask);
    j["converged"] = session.converged() && !vanished;
    j["stop_reason"] = vanished ? "vanished" : model::stopReasonName(run.result.stopReason);
    if (const auto& leak = run.result.leak) {
        // Where the surface broke through: voxel indices and the scanner's millimetres.
        const glm::vec3 c = leak->centre();
        const glm::dvec3 mm = geometry.indexToWorld(glm::dvec3(c));
        j["leak"] = {
            {"iteration", leak->iteration},
            {"watch", model::leakSignName(leak->sign)},
            {"centre_ijk", {c.x, c.y, c.z}},
            {"box_ijk", {leak->lo.x, leak->lo.y, leak->lo.z, leak->hi.x, leak->hi.y, leak->hi.z}},
            {"centre_lps_mm", {mm.x, mm.y, mm.z}}};
    }
    j["barriers"] = stats.barriers;
    j["growth_rate"] = stats.growthRate;
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
    if (const auto& ref = context.reference) {
        nlohmann::ordered_json r;
        r["file"] = ref->file;
        r["label"] = ref->label < 0 ? nlohmann::ordered_json("non-zero")
                                    : nlohmann::ordered_json(ref->label);
        r["voxels"] = ref->overlap.reference;
        r["overlap_voxels"] = ref->overlap.both;
        r["dice"] = ref->overlap.dice();
        j["reference"] = r;
    }
    j["renderer"] = context.renderer;
    return j.dump(2);
}

} // namespace steerseg::session
