#include "speed/speed_values.hpp"

#include "common/bindings.h"
#include "gpu/gl_counts.hpp"
#include "gpu/gl_error.hpp"
#include "gpu/gl_state_guard.hpp"
#include "gpu/program.hpp"
#include "speed/volume_texture.hpp"

#include <stdexcept>

namespace steerseg::speed {

static_assert(SOLVER_SCAN_UNIT == SPEED_SOURCE_UNIT,
              "speed_values.comp reads the intensity where runVolumePass binds its source");

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
    glUniform1f(glGetUniformLocation(id, "T"), params.T);
    glUniform1f(glGetUniformLocation(id, "eps"), params.eps);
    glUniform1i(glGetUniformLocation(id, "speedKind"), static_cast<GLint>(inputs.kind));
    glUniform1i(glGetUniformLocation(id, "classifyWithinWindow"), inputs.withinWindow ? 1 : 0);
    // The factor texture and the intensity may have been written by image stores just before.
    gpu::memoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT);
    // The factor on its unit; the intensity on SPEED_SOURCE_UNIT, the one volume pass's source.
    bindSpeedTextures(inputs, rawScan, SOLVER_SCAN_UNIT, SOLVER_FACTOR_UNIT);
    runVolumePass(id, inputs.intensity != 0 ? inputs.intensity : rawScan, out.id(), dims);
    gpu::checkGl("evaluating the speed at every voxel");
    return out;
}

} // namespace steerseg::speed
