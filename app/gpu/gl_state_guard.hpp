#pragma once

#include "gpu/gl.hpp"

#include <array>

namespace steerseg::gpu {

// The GL state policy of steerseg: every public entry point of the solver and the renderer
// that issues GL calls holds one of these, which saves on construction every piece of GL state
// those passes change and restores it on destruction. Callers (a UI drawing with Dear ImGui in
// the same context, the other of solver and renderer) therefore find the context as they left
// it, and no pass may assume defaults: each binds what it reads. Covered: texture units
// 0..kTextureUnits-1 (2D and 3D), SSBO bindings 0..kStorageBindings-1 (clamped to the
// context's limit) and the generic SSBO, copy-read/-write and dispatch-indirect bindings, image
// unit 0, the program, framebuffers, pixel pack/unpack buffers and alignments.
class GlStateGuard {
  public:
    static constexpr int kTextureUnits = 8;
    static constexpr int kStorageBindings = 16;

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
    int storageBindings_ = 0;
    std::array<RangeBinding, kStorageBindings> storage_{};
    GLint storageGeneric_ = 0;
    GLint copyRead_ = 0;
    GLint copyWrite_ = 0;
    GLint dispatchIndirect_ = 0;
    ImageBinding image0_;
    GLint readFramebuffer_ = 0;
    GLint drawFramebuffer_ = 0;
    GLint packBuffer_ = 0;
    GLint unpackBuffer_ = 0;
    GLint packAlignment_ = 4;
    GLint unpackAlignment_ = 4;
};

} // namespace steerseg::gpu
