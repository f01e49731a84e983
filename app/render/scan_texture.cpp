#include "render/scan_texture.hpp"

#include "gpu/gl_error.hpp"
#include "gpu/gpu_info.hpp"
#include "render/gl_state_guard.hpp"

#include <algorithm>
#include <limits>
#include <stdexcept>

namespace steerseg::render {

namespace {

std::size_t linear(const glm::ivec3& dims, int i, int j, int k) {
    return static_cast<std::size_t>(i) +
           static_cast<std::size_t>(dims.x) *
               (static_cast<std::size_t>(j) +
                static_cast<std::size_t>(dims.y) * static_cast<std::size_t>(k));
}

} // namespace

std::vector<float> blockMinMax(const std::vector<float>& values, const glm::ivec3& dims) {
    const glm::ivec3 grid = (dims + kSkipBlock - 1) / kSkipBlock;
    std::vector<float> out(static_cast<std::size_t>(grid.x) * grid.y * grid.z * 2);
    for (int bz = 0; bz < grid.z; ++bz) {
        for (int by = 0; by < grid.y; ++by) {
            for (int bx = 0; bx < grid.x; ++bx) {
                const glm::ivec3 lo = glm::max(glm::ivec3(bx, by, bz) * kSkipBlock - 1, 0);
                const glm::ivec3 hi =
                    glm::min(glm::ivec3(bx, by, bz) * kSkipBlock + kSkipBlock + 1, dims);
                float mn = std::numeric_limits<float>::max();
                float mx = std::numeric_limits<float>::lowest();
                for (int k = lo.z; k < hi.z; ++k) {
                    for (int j = lo.y; j < hi.y; ++j) {
                        for (int i = lo.x; i < hi.x; ++i) {
                            const float v = values[linear(dims, i, j, k)];
                            mn = std::min(mn, v);
                            mx = std::max(mx, v);
                        }
                    }
                }
                const std::size_t at = 2 * linear(grid, bx, by, bz);
                out[at] = mn;
                out[at + 1] = mx;
            }
        }
    }
    return out;
}

ScanTexture::ScanTexture(const Volume& volume, GLuint shared) : dims_(volume.dims()) {
    const IntensityStats& stats = volume.stats();
    min_ = stats.min;
    max_ = stats.max > stats.min ? stats.max : stats.min + 1.0;
    std::vector<float> normalised = volume.realValues();
    for (float& v : normalised) {
        v = static_cast<float>(normalise(static_cast<double>(v)));
    }
    GlStateGuard guard;
    glActiveTexture(GL_TEXTURE0);
    if (shared != 0 && gpu::queryGpuInfo().floatLinearFiltering) {
        // The solver reads this texture with texelFetch only, which ignores these parameters.
        shared_ = shared;
        glBindTexture(GL_TEXTURE_3D, shared_);
        glm::ivec3 size{0};
        glGetTexLevelParameteriv(GL_TEXTURE_3D, 0, GL_TEXTURE_WIDTH, &size.x);
        glGetTexLevelParameteriv(GL_TEXTURE_3D, 0, GL_TEXTURE_HEIGHT, &size.y);
        glGetTexLevelParameteriv(GL_TEXTURE_3D, 0, GL_TEXTURE_DEPTH, &size.z);
        if (size != dims_) {
            throw std::invalid_argument("the shared scan texture is not this scan's size");
        }
    } else {
        glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
        texture_ = gpu::createTexture();
        glBindTexture(GL_TEXTURE_3D, texture_.id());
        glTexStorage3D(GL_TEXTURE_3D, 1, GL_R16F, dims_.x, dims_.y, dims_.z);
        glTexSubImage3D(GL_TEXTURE_3D, 0, 0, 0, 0, dims_.x, dims_.y, dims_.z, GL_RED, GL_FLOAT,
                        normalised.data());
    }
    glTexParameteri(GL_TEXTURE_3D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_3D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    for (GLenum wrap : {GL_TEXTURE_WRAP_S, GL_TEXTURE_WRAP_T, GL_TEXTURE_WRAP_R}) {
        glTexParameteri(GL_TEXTURE_3D, wrap, GL_CLAMP_TO_EDGE);
    }
    gpu::checkGl("uploading the scan texture");

    gridDims_ = (dims_ + kSkipBlock - 1) / kSkipBlock;
    const std::vector<float> minMax = blockMinMax(normalised, dims_);
    grid_ = gpu::createTexture();
    glBindTexture(GL_TEXTURE_3D, grid_.id());
    glTexStorage3D(GL_TEXTURE_3D, 1, GL_RG16F, gridDims_.x, gridDims_.y, gridDims_.z);
    glTexSubImage3D(GL_TEXTURE_3D, 0, 0, 0, 0, gridDims_.x, gridDims_.y, gridDims_.z, GL_RG,
                    GL_FLOAT, minMax.data());
    glTexParameteri(GL_TEXTURE_3D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_3D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    gpu::checkGl("uploading the skipping grid");
}

glm::vec2 ScanTexture::toNormalised() const {
    if (shared_ == 0) {
        return {1.0F, 0.0F};
    }
    return {static_cast<float>(1.0 / (max_ - min_)), static_cast<float>(-min_ / (max_ - min_))};
}

double ScanTexture::normalise(double real) const {
    return (real - min_) / (max_ - min_);
}

} // namespace steerseg::render
