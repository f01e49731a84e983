#pragma once

#include "gpu/gl.hpp"

#include <array>

namespace steerseg::render {

// Saves, on construction, every piece of GL state the renderer changes and restores it on
// destruction, so a UI drawing in the same context (Dear ImGui) finds its state untouched.
// Units covered: texture units 0..kTextureUnits-1 (2D and 3D), SSBO bindings
// 0..kStorageBindings-1, image unit 0, program, framebuffers, pixel pack/unpack.
class GlStateGuard {
  public:
    static constexpr int kTextureUnits = 4;
    static constexpr int kStorageBindings = 4;

    GlStateGuard();
    ~GlStateGuard();
    GlStateGuard(const GlStateGuard&) = delete;
    GlStateGuard& operator=(const GlStateGuard&) = delete;

  private:
    struct RangeBinding {
        GLint buffer = 0;
        GLint64 start = 0;
        GLint64 size = 0;
    };
    struct ImageBinding {
        GLint texture = 0;
        GLint level = 0;
        GLboolean layered = GL_FALSE;
        GLint layer = 0;
        GLint access = GL_READ_ONLY;
        GLint format = GL_R32UI;
    };
    GLint program_ = 0;
    GLint activeTexture_ = GL_TEXTURE0;
    std::array<GLint, kTextureUnits> texture2d_{};
    std::array<GLint, kTextureUnits> texture3d_{};
    std::array<RangeBinding, kStorageBindings> storage_{};
    GLint storageGeneric_ = 0;
    ImageBinding image0_;
    GLint readFramebuffer_ = 0;
    GLint drawFramebuffer_ = 0;
    GLint packBuffer_ = 0;
    GLint unpackBuffer_ = 0;
    GLint packAlignment_ = 4;
    GLint unpackAlignment_ = 4;
};

} // namespace steerseg::render
