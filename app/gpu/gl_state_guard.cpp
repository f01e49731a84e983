#include "gpu/gl_state_guard.hpp"

#include <algorithm>

namespace steerseg::gpu {

GlStateGuard::GlStateGuard() {
    glGetIntegerv(GL_CURRENT_PROGRAM, &program_);
    glGetIntegerv(GL_ACTIVE_TEXTURE, &activeTexture_);
    for (int u = 0; u < kTextureUnits; ++u) {
        glActiveTexture(static_cast<GLenum>(GL_TEXTURE0 + u));
        glGetIntegerv(GL_TEXTURE_BINDING_2D, &texture2d_[static_cast<std::size_t>(u)]);
        glGetIntegerv(GL_TEXTURE_BINDING_3D, &texture3d_[static_cast<std::size_t>(u)]);
    }
    glActiveTexture(static_cast<GLenum>(activeTexture_));
    GLint maxBindings = 0;
    glGetIntegerv(GL_MAX_SHADER_STORAGE_BUFFER_BINDINGS, &maxBindings);
    storageBindings_ = std::min(maxBindings, kStorageBindings);
    for (int b = 0; b < storageBindings_; ++b) {
        RangeBinding& r = storage_[static_cast<std::size_t>(b)];
        const auto index = static_cast<GLuint>(b);
        glGetIntegeri_v(GL_SHADER_STORAGE_BUFFER_BINDING, index, &r.buffer);
        glGetInteger64i_v(GL_SHADER_STORAGE_BUFFER_START, index, &r.start);
        glGetInteger64i_v(GL_SHADER_STORAGE_BUFFER_SIZE, index, &r.size);
    }
    glGetIntegerv(GL_SHADER_STORAGE_BUFFER_BINDING, &storageGeneric_);
    glGetIntegerv(GL_COPY_READ_BUFFER_BINDING, &copyRead_);
    glGetIntegerv(GL_COPY_WRITE_BUFFER_BINDING, &copyWrite_);
    glGetIntegerv(GL_DISPATCH_INDIRECT_BUFFER_BINDING, &dispatchIndirect_);
    glGetIntegeri_v(GL_IMAGE_BINDING_NAME, 0, &image0_.texture);
    glGetIntegeri_v(GL_IMAGE_BINDING_LEVEL, 0, &image0_.level);
    GLint layered = 0;
    glGetIntegeri_v(GL_IMAGE_BINDING_LAYERED, 0, &layered);
    image0_.layered = layered != 0 ? GL_TRUE : GL_FALSE;
    glGetIntegeri_v(GL_IMAGE_BINDING_LAYER, 0, &image0_.layer);
    glGetIntegeri_v(GL_IMAGE_BINDING_ACCESS, 0, &image0_.access);
    glGetIntegeri_v(GL_IMAGE_BINDING_FORMAT, 0, &image0_.format);
    glGetIntegerv(GL_READ_FRAMEBUFFER_BINDING, &readFramebuffer_);
    glGetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &drawFramebuffer_);
    glGetIntegerv(GL_PIXEL_PACK_BUFFER_BINDING, &packBuffer_);
    glGetIntegerv(GL_PIXEL_UNPACK_BUFFER_BINDING, &unpackBuffer_);
    glGetIntegerv(GL_PACK_ALIGNMENT, &packAlignment_);
    glGetIntegerv(GL_UNPACK_ALIGNMENT, &unpackAlignment_);
}

GlStateGuard::~GlStateGuard() {
    glUseProgram(static_cast<GLuint>(program_));
    for (int u = 0; u < kTextureUnits; ++u) {
        glActiveTexture(static_cast<GLenum>(GL_TEXTURE0 + u));
        glBindTexture(GL_TEXTURE_2D, static_cast<GLuint>(texture2d_[static_cast<std::size_t>(u)]));
        glBindTexture(GL_TEXTURE_3D, static_cast<GLuint>(texture3d_[static_cast<std::size_t>(u)]));
    }
    glActiveTexture(static_cast<GLenum>(activeTexture_));
    for (int b = 0; b < storageBindings_; ++b) {
        const RangeBinding& r = storage_[static_cast<std::size_t>(b)];
        const auto index = static_cast<GLuint>(b);
        if (r.buffer != 0 && r.size > 0) {
            glBindBufferRange(GL_SHADER_STORAGE_BUFFER, index, static_cast<GLuint>(r.buffer),
                              static_cast<GLintptr>(r.start), static_cast<GLsizeiptr>(r.size));
        } else {
            glBindBufferBase(GL_SHADER_STORAGE_BUFFER, index, static_cast<GLuint>(r.buffer));
        }
    }
    glBindBuffer(GL_SHADER_STORAGE_BUFFER, static_cast<GLuint>(storageGeneric_));
    glBindBuffer(GL_COPY_READ_BUFFER, static_cast<GLuint>(copyRead_));
    glBindBuffer(GL_COPY_WRITE_BUFFER, static_cast<GLuint>(copyWrite_));
    glBindBuffer(GL_DISPATCH_INDIRECT_BUFFER, static_cast<GLuint>(dispatchIndirect_));
    glBindImageTexture(0, static_cast<GLuint>(image0_.texture), image0_.level, image0_.layered,
                       image0_.layer, static_cast<GLenum>(image0_.access),
                       static_cast<GLenum>(image0_.format));
    glBindFramebuffer(GL_READ_FRAMEBUFFER, static_cast<GLuint>(readFramebuffer_));
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, static_cast<GLuint>(drawFramebuffer_));
    glBindBuffer(GL_PIXEL_PACK_BUFFER, static_cast<GLuint>(packBuffer_));
    glBindBuffer(GL_PIXEL_UNPACK_BUFFER, static_cast<GLuint>(unpackBuffer_));
    glPixelStorei(GL_PACK_ALIGNMENT, packAlignment_);
    glPixelStorei(GL_UNPACK_ALIGNMENT, unpackAlignment_);
}

} // namespace steerseg::gpu
