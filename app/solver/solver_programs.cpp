#include "solver/solver_programs.hpp"

#include "gpu/program.hpp"
#include "model/level_set_params.hpp"

#include <cstdio>
#include <string>

namespace steerseg::solver::detail {

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
