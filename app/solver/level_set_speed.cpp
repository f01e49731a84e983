// The data term's inputs: which textures the speed passes read, and the classify speed
// evaluated where the front goes (solver/speed_on_demand.hpp, docs/speed.md).
#include "common/bindings.h"
#include "gpu/gl_error.hpp"
#include "gpu/gl_state_guard.hpp"
#include "solver/gpu_brick_pool.hpp"
#include "solver/level_set_solver.hpp"
#include "solver/solver_programs.hpp"
#include "solver/speed_on_demand.hpp"
#include "solver/voxel_bits.hpp"

#include <algorithm>
#include <cstdint>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

namespace steerseg::solver {

void LevelSetSolver::setSpeedInputs(const speed::SpeedInputs& inputs) {
    speed::validateSpeedInputs(inputs);
    gpu::GlStateGuard guard;
    if (inputs.onDemand.nodes != 0) {
        if (!onDemand_) {
            onDemand_ = std::make_unique<detail::SpeedOnDemand>(
                dims_, pool_->brickGrid(), options_.brickSize, programs_->localSize);
        }
        onDemand_->reset();
    }
    speedInputs_ = inputs;
    const GLuint p = programs_->measureSpeed.id(); // the one pass that evaluates the speed
    glProgramUniform1i(p, glGetUniformLocation(p, "speedKind"), static_cast<GLint>(inputs.kind));
    glProgramUniform1i(p, glGetUniformLocation(p, "classifyWithinWindow"),
                       inputs.withinWindow ? 1 : 0);
    pool_->forgetSpeed();
    noteChange();
}

bool LevelSetSolver::speedOnDemand() const {
    return speedInputs_.onDemand.nodes != 0;
}

void LevelSetSolver::setClaimed(std::span<const std::uint8_t> claimed) {
    gpu::GlStateGuard guard;
    claimed_ = detail::uploadVoxelBits(claimed, dims_, SOLVER_CLAIMED_UNIT, "claimed");
    const GLuint p = programs_->measureSpeed.id(); // the one pass that evaluates the speed
    glProgramUniform1i(p, glGetUniformLocation(p, "hasClaimed"), claimed_ ? 1 : 0);
    pool_->forgetSpeed();
    noteChange(); // a surface over newly claimed voxels recedes from every brick
}

void LevelSetSolver::setKept(std::span<const std::uint8_t> kept) {
    gpu::GlStateGuard guard;
    kept_ = detail::uploadVoxelBits(kept, dims_, SOLVER_KEPT_UNIT, "kept");
    const GLuint p = programs_->measureSpeed.id();
    glProgramUniform1i(p, glGetUniformLocation(p, "hasKept"), kept_ ? 1 : 0);
    pool_->forgetSpeed();
    noteChange(); // released, the voxels' speeds are the data's again
}

// The textures and buffers the data speed's passes read, before a run of them.
void LevelSetSolver::bindSpeed() const {
    speed::bindSpeedTextures(speedInputs_, scan_->exact(), SOLVER_SCAN_UNIT, SOLVER_FACTOR_UNIT);
    if (claimed_) {
        glActiveTexture(GL_TEXTURE0 + SOLVER_CLAIMED_UNIT);
        glBindTexture(GL_TEXTURE_3D, claimed_.id());
    }
    if (kept_) {
        glActiveTexture(GL_TEXTURE0 + SOLVER_KEPT_UNIT);
        glBindTexture(GL_TEXTURE_3D, kept_.id());
    }
    if (speedOnDemand()) {
        onDemand_->bind(speedInputs_);
    }
}

std::uint32_t LevelSetSolver::evaluateSpeedAhead(std::uint32_t maxBricks) {
    if (!speedOnDemand()) {
        return 0;
    }
    if (maxBricks == 0 || onDemand_->aheadLeft() == 0) {
        return onDemand_->aheadLeft(); // no GL work: a frame loop may ask every frame
    }
    gpu::GlStateGuard guard;
    pool_->bind();
    bindSpeed();
    const std::uint32_t left = onDemand_->evaluateAhead(maxBricks);
    gpu::checkGl("evaluating the speed ahead of the front");
    return left;
}

std::uint32_t LevelSetSolver::speedBricksEvaluated() const {
    if (!speedOnDemand()) {
        return 0;
    }
    gpu::GlStateGuard guard;
    return onDemand_->evaluatedBricks();
}

} // namespace steerseg::solver
