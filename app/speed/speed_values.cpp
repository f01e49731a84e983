#include "speed/speed_values.hpp"

#include "common/bindings.h"
#include "gpu/gl_counts.hpp"
#include "gpu/gl_error.hpp"
#include "gpu/gl_state_guard.hpp"
#include "gpu/program.hpp"
#include "speed/volume_texture.hpp"

#include <stdexcept>

namespace steerseg::speed {

gpu::Texture speedValues(const SpeedInputs& inputs, GLuint rawScan, const glm::ivec3& dims,
                         const model::LevelSetParams& params) {
    validateSpeedInputs(inputs);
    if (inputs.onDemand.nodes != 0) {
        throw std::invalid_argument("speed values: a classify speed evaluated on demand is not "
                                    "complete");
    }
    gpu::GlStateGuard guard;
    const gpu::Program program = gpu::buildComputeProgram("speed/speed_values.comp");
    gpu::Texture out = createVolumeTexture(dims, "speed values");
    const GLuint id = program.id();
    glUseProgram(id);
    glUniform3i(glGetUniformLocation(id, "volumeDims"), dims.x, dims.y, dims.z);
    glUniform1f(glGetUniformLocation(id, "T"), params.T);
    glUniform1f(glGetUniformLocation(id, "eps"), params.eps);
    glUniform1i(glGetUniformLocation(id, "speedKind"), static_cast<GLint>(inputs.kind));
    glUniform1i(glGetUniformLocation(id, "classifyWithinWindow"), inputs.withinWindow ? 1 : 0);
    // The factor texture and the intensity may have been written by image stores just before.
    gpu::memoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT);
    bindSpeedTextures(inputs, rawScan, SOLVER_SCAN_UNIT, SOLVER_FACTOR_UNIT);
    glBindImageTexture(SPEED_OUT_IMAGE_UNIT, out.id(), 0, GL_TRUE, 0, GL_WRITE_ONLY, GL_R32F);
    gpu::dispatchCompute(static_cast<GLuint>((dims.x + 3) / 4),
                         static_cast<GLuint>((dims.y + 3) / 4),
                         static_cast<GLuint>((dims.z + 3) / 4));
    gpu::memoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT | GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);
    gpu::checkGl("evaluating the speed at every voxel");
    return out;
}

} // namespace steerseg::speed
