#include "solver/solver_programs.hpp"

#include "gpu/gpu_info.hpp"
#include "gpu/program.hpp"
#include "model/level_set_params.hpp"

#include <algorithm>
#include <cstdio>
#include <string>

namespace steerseg::solver::detail {

// A GPU gets 64 invocations a brick, enough to keep its lanes busy over 512 voxels. A CPU
// rasterizer (llvmpipe) runs a group one SIMD vector of invocations at a time and switches
// between those vectors at every barrier(): a group of one vector (8 lanes on 256-bit AVX)
// stepped a small front 1.2-1.45x as fast as 64 and a large one 1.15-1.2x (docs/solver-log.md,
// 2026-12-05).
int brickGroupSize(int brickSize, int requested, const std::string& renderer) {
    if (requested != 0) {
        return requested;
    }
    const int brickVoxels = brickSize * brickSize * brickSize;
    const int lanes = gpu::cpuRasterizerLanes(renderer);
    return std::min(brickVoxels, lanes > 0 ? lanes : 64);
}

gpu::Defines solverDefines(int brickSize, int localSize) {
    char far[32];
    std::snprintf(far, sizeof far, "%.1f", static_cast<double>(model::kPhiFar));
    char rescale[32];
    std::snprintf(rescale, sizeof rescale, "%.4f", static_cast<double>(model::kRescaleWeight));
    return {{"BRICK_SIZE", std::to_string(brickSize)},
            {"PHI_FAR", far},
            {"RESCALE_WEIGHT", rescale},
            {"LOCAL_SIZE", std::to_string(localSize)},
            {"MAX_BARRIERS", std::to_string(model::kMaxBarriers)}};
}

SolverPrograms::SolverPrograms(int brickSize, int groupSize) : localSize(groupSize) {
    const gpu::Defines d = solverDefines(brickSize, groupSize);
    beginIteration = gpu::buildComputeProgram("solver/begin_iteration.comp", d);
    allocateBricks = gpu::buildComputeProgram("solver/allocate_bricks.comp", d);
    buildActiveList = gpu::buildComputeProgram("solver/build_active_list.comp", d);
    measureSpeed = gpu::buildComputeProgram("solver/measure_speed.comp", d);
    updatePhi = gpu::buildComputeProgram("solver/update_phi.comp", d);
    settleBricks = gpu::buildComputeProgram("solver/settle_bricks.comp", d);
    classifyBricks = gpu::buildComputeProgram("solver/classify_bricks.comp", d);
    requestEditBricks = gpu::buildComputeProgram("solver/request_edit_bricks.comp", d);
    applySphere = gpu::buildComputeProgram("solver/apply_sphere.comp", d);
}

} // namespace steerseg::solver::detail
