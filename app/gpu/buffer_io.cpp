#include "gpu/buffer_io.hpp"

#include "gpu/gl_counts.hpp"
#include "gpu/gl_error.hpp"

#include <cstring>
#include <string>

namespace steerseg::gpu {

void readBufferBytes(const Buffer& buffer, std::size_t offset, void* out, std::size_t bytes,
                     std::string_view what) {
    if (bytes == 0) {
        return;
    }
    const auto size = static_cast<GLsizeiptr>(bytes);
    countReadBack();
    // Read through a staging copy: on the H100's driver a buffer mapped directly after the
    // shaders' last dispatch lacked that dispatch's atomics (the solver's requestCount read 0
    // where the next iteration served requests), even after GL_BUFFER_UPDATE_BARRIER_BIT and
    // glFinish.
    gpu::memoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
    const Buffer staging = createBuffer(GL_COPY_WRITE_BUFFER, size, nullptr, GL_STREAM_READ);
    glBindBuffer(GL_COPY_READ_BUFFER, buffer.id());
    glBindBuffer(GL_COPY_WRITE_BUFFER, staging.id());
    glCopyBufferSubData(GL_COPY_READ_BUFFER, GL_COPY_WRITE_BUFFER, static_cast<GLintptr>(offset), 0,
                        size);
    const void* mapped = glMapBufferRange(GL_COPY_WRITE_BUFFER, 0, size, GL_MAP_READ_BIT);
    if (mapped == nullptr) {
        checkGl(("mapping " + std::string(what)).c_str());
        throw GlError("mapping " + std::string(what) + " failed");
    }
    std::memcpy(out, mapped, bytes);
    glUnmapBuffer(GL_COPY_WRITE_BUFFER);
}

void writeBuffer(const Buffer& buffer, std::size_t offset, const void* data, std::size_t bytes) {
    if (bytes == 0) {
        return;
    }
    gpu::memoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
    glBindBuffer(GL_SHADER_STORAGE_BUFFER, buffer.id());
    glBufferSubData(GL_SHADER_STORAGE_BUFFER, static_cast<GLintptr>(offset),
                    static_cast<GLsizeiptr>(bytes), data);
}

} // namespace steerseg::gpu
