// The data term's inputs: which textures the speed passes read, and the classify speed
// evaluated where the front goes (solver/speed_on_demand.hpp, docs/speed.md).
#include "common/bindings.h"
#include "gpu/gl_error.hpp"
#include "gpu/gl_state_guard.hpp"
#include "solver/gpu_brick_pool.hpp"
#include "solver/level_set_solver.hpp"
#include "solver/solver_programs.hpp"
#include "solver/speed_on_demand.hpp"

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

// One bit a voxel, 32 along i to a texel: an eighth of an R8UI texture's memory (33 MiB rather
// than 262 MiB at 512x512x1000, on llvmpipe host memory beside the scan's), for one shift and
// mask more in the pass that fills a brick's speeds once.
void LevelSetSolver::setClaimed(std::span<const std::uint8_t> claimed) {
    const std::size_t voxels = static_cast<std::size_t>(dims_.x) *
                               static_cast<std::size_t>(dims_.y) *
                               static_cast<std::size_t>(dims_.z);
    if (!claimed.empty() && claimed.size() != voxels) {
        throw std::invalid_argument("claimed mask has " + std::to_string(claimed.size()) +
                                    " voxels but the scan " + std::to_string(voxels));
    }
    gpu::GlStateGuard guard;
    const bool any =
        std::any_of(claimed.begin(), claimed.end(), [](std::uint8_t v) { return v != 0; });
    claimed_.reset();
    if (any) {
        const glm::ivec3 packed((dims_.x + 31) / 32, dims_.y, dims_.z);
        std::vector<std::uint32_t> bits(static_cast<std::size_t>(packed.x) *
                                        static_cast<std::size_t>(packed.y) *
                                        static_cast<std::size_t>(packed.z));
        std::size_t v = 0;
        for (std::size_t row = 0; row < voxels / static_cast<std::size_t>(dims_.x); ++row) {
            std::uint32_t* words = bits.data() + row * static_cast<std::size_t>(packed.x);
            for (int i = 0; i < dims_.x; ++i, ++v) {
                if (claimed[v] != 0) {
                    words[i / 32] |= 1U << (i % 32);
                }
            }
        }
        claimed_ = gpu::createTexture();
        glActiveTexture(GL_TEXTURE0 + SOLVER_CLAIMED_UNIT);
        glBindTexture(GL_TEXTURE_3D, claimed_.id());
        glTexStorage3D(GL_TEXTURE_3D, 1, GL_R32UI, packed.x, packed.y, packed.z);
        // An integer texture filtered other than NEAREST is incomplete, even for texelFetch.
        glTexParameteri(GL_TEXTURE_3D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
        glTexParameteri(GL_TEXTURE_3D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
        glBindBuffer(GL_PIXEL_UNPACK_BUFFER, 0);
        glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
        glTexSubImage3D(GL_TEXTURE_3D, 0, 0, 0, 0, packed.x, packed.y, packed.z, GL_RED_INTEGER,
                        GL_UNSIGNED_INT, bits.data());
        gpu::checkGl("uploading the claimed voxels");
    }
    const GLuint p = programs_->measureSpeed.id(); // the one pass that evaluates the speed
    glProgramUniform1i(p, glGetUniformLocation(p, "hasClaimed"), any ? 1 : 0);
    pool_->forgetSpeed();
    noteChange(); // a surface over newly claimed voxels recedes from every brick
}

// The textures and buffers the data speed's passes read, before a run of them.
void LevelSetSolver::bindSpeed() const {
    speed::bindSpeedTextures(speedInputs_, scan_->exact(), SOLVER_SCAN_UNIT, SOLVER_FACTOR_UNIT);
    if (claimed_) {
        glActiveTexture(GL_TEXTURE0 + SOLVER_CLAIMED_UNIT);
        glBindTexture(GL_TEXTURE_3D, claimed_.id());
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
