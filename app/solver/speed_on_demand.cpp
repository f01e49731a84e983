#include "solver/speed_on_demand.hpp"

#include "common/bindings.h"
#include "gpu/buffer_io.hpp"
#include "gpu/gl_counts.hpp"
#include "gpu/gl_error.hpp"
#include "gpu/program.hpp"
#include "solver/solver_programs.hpp"
#include "speed/classifier_speed.hpp"

#include <algorithm>
#include <vector>

namespace steerseg::solver::detail {

SpeedOnDemand::SpeedOnDemand(const glm::ivec3& dims, const glm::ivec3& brickGrid, int brickSize,
                             int localSize)
    : program_(gpu::buildComputeProgram("solver/evaluate_speed.comp",
                                        solverDefines(brickSize, localSize))),
      bricks_(static_cast<std::uint32_t>(brickGrid.x * brickGrid.y * brickGrid.z)), dims_(dims) {
    gpu::Defines allocateDefines = solverDefines(brickSize, localSize);
    allocateDefines.emplace_back("EVALUATE_SPEED", "1");
    allocate_ = gpu::buildComputeProgram("solver/allocate_bricks.comp", allocateDefines);
    for (const GLuint p : {program_.id(), allocate_.id()}) {
        glProgramUniform3i(p, glGetUniformLocation(p, "volumeDims"), dims.x, dims.y, dims.z);
        glProgramUniform3i(p, glGetUniformLocation(p, "brickGrid"), brickGrid.x, brickGrid.y,
                           brickGrid.z);
    }
    ready_ = gpu::createBuffer(GL_SHADER_STORAGE_BUFFER,
                               static_cast<GLsizeiptr>((bricks_ + 1U) * sizeof(std::uint32_t)),
                               nullptr, GL_DYNAMIC_COPY);
    reset();
}

void SpeedOnDemand::reset() {
    const std::vector<std::uint32_t> zeros(bricks_ + 1U, 0U);
    gpu::writeBuffer(ready_, 0, zeros.data(), zeros.size() * sizeof(std::uint32_t));
    aheadCursor_ = 0;
}

void SpeedOnDemand::bind(const speed::SpeedInputs& inputs) const {
    speed::bindClassifierForest(program_.id(), inputs.onDemand, dims_);
    speed::bindClassifierForest(allocate_.id(), inputs.onDemand, dims_);
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, SPEED_READY_BINDING, ready_.id());
    glBindImageTexture(SOLVER_SPEED_IMAGE_UNIT, inputs.factor, 0, GL_TRUE, 0, GL_WRITE_ONLY,
                       GL_R32F);
}

void SpeedOnDemand::evaluateActive(GLintptr argsOffset) const {
    glUseProgram(program_.id());
    glUniform1i(glGetUniformLocation(program_.id(), "fromActiveList"), 1);
    gpu::dispatchComputeIndirect(argsOffset);
    finishPass();
}

void SpeedOnDemand::allocate(GLintptr argsOffset) const {
    glUseProgram(allocate_.id());
    gpu::dispatchComputeIndirect(argsOffset);
    finishPass();
}

std::uint32_t SpeedOnDemand::evaluateAhead(std::uint32_t maxBricks) {
    // One group per brick along x, within the 65535 groups GLES 3.1 guarantees.
    const std::uint32_t count = std::min({maxBricks, aheadLeft(), 65535U});
    if (count > 0) {
        const GLuint p = program_.id();
        glUseProgram(p);
        glUniform1i(glGetUniformLocation(p, "fromActiveList"), 0);
        glUniform1ui(glGetUniformLocation(p, "firstBrick"), aheadCursor_);
        gpu::dispatchCompute(count, 1, 1);
        finishPass();
        aheadCursor_ += count;
    }
    return aheadLeft();
}

// The data speed's readers fetch the texture, and the next pass reads the ready words.
void SpeedOnDemand::finishPass() const {
    gpu::memoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT | GL_SHADER_IMAGE_ACCESS_BARRIER_BIT |
                       GL_SHADER_STORAGE_BARRIER_BIT | GL_COMMAND_BARRIER_BIT);
}

std::uint32_t SpeedOnDemand::evaluatedBricks() const {
    std::uint32_t count = 0;
    gpu::readBufferBytes(ready_, 0, &count, sizeof count, "the speed's ready bricks");
    return count;
}

} // namespace steerseg::solver::detail
