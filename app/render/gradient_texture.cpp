#include "render/gradient_texture.hpp"

#include "common/bindings.h"
#include "gpu/gl_counts.hpp"
#include "gpu/gl_error.hpp"
#include "gpu/gl_state_guard.hpp"
#include "gpu/gpu_limits.hpp"
#include "gpu/program.hpp"

namespace steerseg::render {

namespace {

bool fitsLimits(const glm::ivec3& dims) {
    const int max3d = gpu::gpuLimits().max3dTextureSize;
    return dims.x <= max3d && dims.y <= max3d && dims.z <= max3d;
}

} // namespace

GradientTexture::GradientTexture(const gpu::ScanTexture& scan, std::size_t budget) {
    const glm::ivec3 dims = scan.dims();
    const std::size_t voxels = static_cast<std::size_t>(dims.x) * static_cast<std::size_t>(dims.y) *
                               static_cast<std::size_t>(dims.z);
    gpu::GlStateGuard guard;
    if (voxels * 8 > budget || !fitsLimits(dims)) {
        return;
    }
    // Full floats where the budget allows: llvmpipe filters them faster than half floats (no
    // conversion per texel; the 3D view at 1280x800 on the built-in sample 8 % faster), and the
    // intensity keeps its 24 bits.
    const bool full = voxels * 16 <= budget;
    const GLenum format = full ? GL_RGBA32F : GL_RGBA16F;
    const std::size_t bytes = voxels * (full ? 16 : 8);
    while (glGetError() != GL_NO_ERROR) {
    }
    gpu::Texture texture = gpu::createTexture();
    glActiveTexture(GL_TEXTURE0 + VIEW_GRADIENT_UNIT);
    glBindTexture(GL_TEXTURE_3D, texture.id());
    glTexStorage3D(GL_TEXTURE_3D, 1, format, dims.x, dims.y, dims.z);
    if (glGetError() != GL_NO_ERROR) {
        return; // out of GPU memory: the ray caster differences the scan instead
    }
    glTexParameteri(GL_TEXTURE_3D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_3D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    for (const GLenum wrap : {GL_TEXTURE_WRAP_S, GL_TEXTURE_WRAP_T, GL_TEXTURE_WRAP_R}) {
        glTexParameteri(GL_TEXTURE_3D, wrap, GL_CLAMP_TO_EDGE);
    }
    const gpu::Program program = gpu::buildComputeProgram(
        "render/gradient.comp", {{"GRADIENT_IMAGE_FORMAT", full ? "rgba32f" : "rgba16f"}});
    glUseProgram(program.id());
    glActiveTexture(GL_TEXTURE0 + VIEW_SCAN_UNIT);
    glBindTexture(GL_TEXTURE_3D, scan.display());
    glBindImageTexture(VIEW_GRADIENT_IMAGE_UNIT, texture.id(), 0, GL_TRUE, 0, GL_WRITE_ONLY,
                       format);
    glUniform3i(glGetUniformLocation(program.id(), "volumeDims"), dims.x, dims.y, dims.z);
    const glm::vec2 toNormalised = scan.toNormalised();
    glUniform2f(glGetUniformLocation(program.id(), "toNormalised"), toNormalised.x, toNormalised.y);
    gpu::dispatchCompute(static_cast<GLuint>((dims.x + 3) / 4),
                         static_cast<GLuint>((dims.y + 3) / 4),
                         static_cast<GLuint>((dims.z + 3) / 4));
    gpu::memoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT);
    gpu::checkGl("computing the scan's gradient texture");
    texture_ = std::move(texture);
    bytes_ = bytes;
}

} // namespace steerseg::render
