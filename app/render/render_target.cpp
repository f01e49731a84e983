#include "render/render_target.hpp"

#include "gpu/gl_counts.hpp"
#include "gpu/gl_error.hpp"
#include "gpu/gl_state_guard.hpp"
#include "gpu/gpu_limits.hpp"

#include <stdexcept>
#include <string>

namespace steerseg::render {

void RenderTarget::ensureSize(const glm::ivec2& size) {
    if (size == size_ && texture_) {
        return;
    }
    if (size.x <= 0 || size.y <= 0 || size.x > 16384 || size.y > 16384) {
        throw std::invalid_argument("image size must be 1..16384 pixels per side");
    }
    const int limit = gpu::gpuLimits().maxTextureSize;
    if (size.x > limit || size.y > limit) {
        throw gpu::GpuCapacityError("picture " + std::to_string(size.x) + "x" +
                                    std::to_string(size.y) + " exceeds GL_MAX_TEXTURE_SIZE " +
                                    std::to_string(limit) + " of this GPU");
    }
    gpu::GlStateGuard guard;
    texture_ = gpu::createTexture();
    glActiveTexture(GL_TEXTURE0);
    glBindTexture(GL_TEXTURE_2D, texture_.id());
    glTexStorage2D(GL_TEXTURE_2D, 1, GL_RGBA8, size.x, size.y);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    GLuint fb = 0;
    glGenFramebuffers(1, &fb);
    framebuffer_ = gpu::Framebuffer(fb);
    glBindFramebuffer(GL_READ_FRAMEBUFFER, fb);
    glFramebufferTexture2D(GL_READ_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, texture_.id(),
                           0);
    gpu::checkGl("allocating the render target");
    size_ = size;
}

RgbaImage RenderTarget::readback() const {
    if (!texture_) {
        throw std::logic_error("nothing rendered yet");
    }
    gpu::GlStateGuard guard;
    gpu::memoryBarrier(GL_FRAMEBUFFER_BARRIER_BIT | GL_TEXTURE_UPDATE_BARRIER_BIT);
    glBindFramebuffer(GL_READ_FRAMEBUFFER, framebuffer_.id());
    glBindBuffer(GL_PIXEL_PACK_BUFFER, 0);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    RgbaImage image{size_.x, size_.y, {}};
    image.pixels.resize(static_cast<std::size_t>(size_.x) * static_cast<std::size_t>(size_.y) * 4);
    gpu::countReadBack();
    glReadPixels(0, 0, size_.x, size_.y, GL_RGBA, GL_UNSIGNED_BYTE, image.pixels.data());
    gpu::checkGl("reading the picture back");
    return image;
}

} // namespace steerseg::render
