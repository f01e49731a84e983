#include "speed/edge_factor.hpp"

#include "gpu/gl_error.hpp"
#include "gpu/gl_state_guard.hpp"
#include "gpu/program.hpp"
#include "speed/volume_texture.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

namespace steerseg::speed {

void validateKappa(float kappa) {
    if (!(kappa > 0.0F && std::isfinite(kappa))) {
        throw std::invalid_argument("edge speed: kappa must be a finite number > 0 (got " +
                                    std::to_string(kappa) + ")");
    }
}

gpu::Texture edgeFactor(GLuint intensity, const glm::ivec3& dims, float kappa) {
    validateKappa(kappa);
    gpu::GlStateGuard guard;
    const gpu::Program program = gpu::buildComputeProgram("speed/edge_factor.comp");
    glProgramUniform1f(program.id(), glGetUniformLocation(program.id(), "invKappa"), 1.0F / kappa);
    gpu::Texture factor = createVolumeTexture(dims, "edge factor");
    runVolumePass(program.id(), intensity, factor.id(), dims);
    gpu::checkGl("computing the edge factor");
    return factor;
}

} // namespace steerseg::speed
