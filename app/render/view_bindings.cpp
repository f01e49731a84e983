#include "render/view_bindings.hpp"

#include "common/bindings.h"
#include "gpu/gl_counts.hpp"

#include <algorithm>
#include <stdexcept>

namespace steerseg::render {

GLuint PoolProgram::get(const solver::BrickPoolView* pool) {
    const int brick = pool != nullptr ? pool->brickSize : 8;
    const float far = pool != nullptr ? pool->phiFar : 4.0F;
    if (!program_ || brick != brickSize_ || far != phiFar_) {
        gpu::Defines defines = defines_;
        defines.emplace_back("BRICK_SIZE", std::to_string(brick));
        defines.emplace_back("PHI_FAR", std::to_string(far));
        program_ = gpu::buildComputeProgram(shader_, defines);
        brickSize_ = brick;
        phiFar_ = far;
    }
    return program_.id();
}

GLint uniform(GLuint program, const char* name) {
    return glGetUniformLocation(program, name);
}

void bindCommon(GLuint program, const RenderInputs& in, const ViewParams& params) {
    const glm::ivec3 dims = in.scan.dims();
    if (in.pool != nullptr) {
        if (in.pool->volumeDims != dims) {
            throw std::invalid_argument("the level set's dimensions differ from the scan's");
        }
        if (in.pool->brickSize <= 0 || in.pool->pageTableBuffer == 0 ||
            in.pool->phiPoolBuffer == 0) {
            throw std::invalid_argument("the level set's brick pool is not set up");
        }
    }
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, PAGE_TABLE_BINDING,
                     in.pool != nullptr ? in.pool->pageTableBuffer : in.emptyBuffer);
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, PHI_POOL_BINDING,
                     in.pool != nullptr ? in.pool->phiPoolBuffer : in.emptyBuffer);
    glUniform3i(uniform(program, "volumeDims"), dims.x, dims.y, dims.z);
    const glm::ivec3 grid = in.pool != nullptr ? in.pool->brickGrid : glm::ivec3(1);
    glUniform3i(uniform(program, "brickGrid"), grid.x, grid.y, grid.z);
    glUniform1i(uniform(program, "hasSurface"), in.pool != nullptr ? 1 : 0);
    glUniform2i(uniform(program, "outSize"), params.size.x, params.size.y);
    const double width = std::max(params.window.width, 1e-9);
    const double lo = in.scan.normalise(params.window.level - 0.5 * width);
    const double scale = (in.scan.rangeMax() - in.scan.rangeMin()) / width;
    glUniform2f(uniform(program, "windowRange"), static_cast<float>(lo), static_cast<float>(scale));
    const glm::vec2 toNormalised = in.scan.toNormalised();
    glUniform2f(uniform(program, "scanToNormalised"), toNormalised.x, toNormalised.y);
    glActiveTexture(GL_TEXTURE0 + VIEW_SCAN_UNIT);
    glBindTexture(GL_TEXTURE_3D, in.scan.display());
    glBindImageTexture(VIEW_OUT_IMAGE_UNIT, in.target.texture(), 0, GL_FALSE, 0, GL_WRITE_ONLY,
                       GL_RGBA8);
}

void dispatchRegion(GLuint program, const ViewParams& params) {
    const glm::ivec4 r = params.region;
    const glm::ivec2 first = glm::clamp(glm::ivec2(r.x, r.y), glm::ivec2(0), params.size);
    const glm::ivec2 count =
        r.z < 0 ? params.size - first : glm::min(glm::ivec2(r.z, r.w), params.size - first);
    if (count.x <= 0 || count.y <= 0) {
        return;
    }
    glUniform2i(uniform(program, "firstPixel"), first.x, first.y);
    gpu::dispatchCompute(static_cast<GLuint>((count.x + 7) / 8),
                         static_cast<GLuint>((count.y + 7) / 8), 1);
    gpu::memoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT | GL_TEXTURE_FETCH_BARRIER_BIT |
                       GL_FRAMEBUFFER_BARRIER_BIT | GL_TEXTURE_UPDATE_BARRIER_BIT);
}

} // namespace steerseg::render
