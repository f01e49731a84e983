#include "speed/smoothing.hpp"

#include "gpu/gl_counts.hpp"
#include "gpu/gl_error.hpp"
#include "gpu/gl_state_guard.hpp"
#include "gpu/program.hpp"
#include "speed/volume_texture.hpp"

#include <cmath>
#include <stdexcept>
#include <string>
#include <utility>

namespace steerseg::speed {

void validateSmoothing(const SmoothingParams& params) {
    if (params.iterations < 0 || params.iterations > kMaxSmoothingIterations) {
        throw std::invalid_argument("smoothing iterations must be between 0 and " +
                                    std::to_string(kMaxSmoothingIterations) + " (got " +
                                    std::to_string(params.iterations) + ")");
    }
    if (params.iterations > 0 &&
        !(params.conductance > 0.0F && std::isfinite(params.conductance))) {
        throw std::invalid_argument("smoothing conductance must be a finite number > 0 (got " +
                                    std::to_string(params.conductance) + ")");
    }
}

gpu::Texture smoothScan(GLuint scan, const glm::ivec3& dims, const SmoothingParams& params,
                        const SmoothingProgress& progress) {
    validateSmoothing(params);
    if (params.iterations == 0) {
        return {};
    }
    gpu::GlStateGuard guard;
    const gpu::Program program = gpu::buildComputeProgram("speed/diffuse.comp");
    glProgramUniform1f(program.id(), glGetUniformLocation(program.id(), "timeStep"),
                       kDiffusionTimeStep);
    glProgramUniform1f(program.id(), glGetUniformLocation(program.id(), "invConductance"),
                       1.0F / params.conductance);
    gpu::Texture result = createVolumeTexture(dims, "smoothing");
    gpu::Texture partner =
        params.iterations > 1 ? createVolumeTexture(dims, "smoothing") : gpu::Texture{};
    // The last iteration must land in `result`: with an even count the first goes to the
    // partner.
    const bool firstToPartner = params.iterations % 2 == 0;
    for (int n = 0; n < params.iterations; ++n) {
        const bool toPartner = (n % 2 == 0) == firstToPartner;
        const GLuint source = n == 0 ? scan : (toPartner ? result.id() : partner.id());
        const GLuint target = toPartner ? partner.id() : result.id();
        runVolumePass(program.id(), source, target, dims);
        if (progress) {
            gpu::finish(); // the callback reports work done, not work queued
            progress(n + 1, params.iterations);
        }
    }
    gpu::checkGl("smoothing the scan");
    return result;
}

} // namespace steerseg::speed
