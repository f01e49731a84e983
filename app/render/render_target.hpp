#pragma once

#include "core/rgba_image.hpp"
#include "gpu/gl_handle.hpp"

#include <glm/glm.hpp>

namespace steerseg::render {

// The RGBA8 image the compute shaders write (immutable storage, so it can be bound as an
// image); reallocated when the size changes. Read back for files, or sampled by a UI.
class RenderTarget {
  public:
    void ensureSize(const glm::ivec2& size);
    [[nodiscard]] GLuint texture() const { return texture_.id(); }
    // Its framebuffer, for a caller that draws into the picture with GL (the kiosk's screen).
    [[nodiscard]] GLuint framebuffer() const { return framebuffer_.id(); }
    [[nodiscard]] glm::ivec2 size() const { return size_; }
    // Waits for the GPU and copies the picture out: GL's row 0 first, which is the top of a
    // picture the compute shaders wrote.
    [[nodiscard]] RgbaImage readback() const;

  private:
    gpu::Texture texture_;
    gpu::Framebuffer framebuffer_;
    glm::ivec2 size_{0};
};

} // namespace steerseg::render
