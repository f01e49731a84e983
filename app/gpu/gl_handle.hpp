#pragma once

#include "gpu/gl.hpp"

#include <utility>

namespace steerseg::gpu {

// Move-only owner of one GL object name; Deleter frees it. Objects must be destroyed while
// their context is current, which the owners (solver, renderer) guarantee by living inside it.
template <typename Deleter> class GlHandle {
  public:
    GlHandle() = default;
    explicit GlHandle(GLuint id) : id_(id) {}
    ~GlHandle() { reset(); }
    GlHandle(const GlHandle&) = delete;
    GlHandle& operator=(const GlHandle&) = delete;
    GlHandle(GlHandle&& other) noexcept : id_(std::exchange(other.id_, 0)) {}
    GlHandle& operator=(GlHandle&& other) noexcept {
        if (this != &other) {
            reset();
            id_ = std::exchange(other.id_, 0);
        }
        return *this;
    }
    [[nodiscard]] GLuint id() const { return id_; }
    explicit operator bool() const { return id_ != 0; }
    void reset() {
        if (id_ != 0) {
            Deleter{}(id_);
            id_ = 0;
        }
    }

  private:
    GLuint id_ = 0;
};

struct BufferDeleter {
    void operator()(GLuint id) const { glDeleteBuffers(1, &id); }
};
struct TextureDeleter {
    void operator()(GLuint id) const { glDeleteTextures(1, &id); }
};
struct FramebufferDeleter {
    void operator()(GLuint id) const { glDeleteFramebuffers(1, &id); }
};
struct ProgramDeleter {
    void operator()(GLuint id) const { glDeleteProgram(id); }
};
struct VertexArrayDeleter {
    void operator()(GLuint id) const { glDeleteVertexArrays(1, &id); }
};
struct QueryDeleter {
    void operator()(GLuint id) const { glDeleteQueries(1, &id); }
};

using Buffer = GlHandle<BufferDeleter>;
using Texture = GlHandle<TextureDeleter>;
using Framebuffer = GlHandle<FramebufferDeleter>;
using Program = GlHandle<ProgramDeleter>;
using VertexArray = GlHandle<VertexArrayDeleter>;
using Query = GlHandle<QueryDeleter>;

Buffer createBuffer(GLenum target, GLsizeiptr bytes, const void* data, GLenum usage);
Texture createTexture();

} // namespace steerseg::gpu
