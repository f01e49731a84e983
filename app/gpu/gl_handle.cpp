#include "gpu/gl_handle.hpp"

#include "gpu/gl_error.hpp"

namespace steerseg::gpu {

Buffer createBuffer(GLenum target, GLsizeiptr bytes, const void* data, GLenum usage) {
    GLuint id = 0;
    glGenBuffers(1, &id);
    Buffer buffer(id);
    glBindBuffer(target, id);
    glBufferData(target, bytes, data, usage);
    checkGl("allocating a GPU buffer");
    return buffer;
}

Texture createTexture() {
    GLuint id = 0;
    glGenTextures(1, &id);
    return Texture(id);
}

} // namespace steerseg::gpu
