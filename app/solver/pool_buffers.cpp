#include "solver/pool_buffers.hpp"

#include "gpu/gl_counts.hpp"

#include <algorithm>

namespace steerseg::solver::detail {

gpu::Buffer makeBuffer(std::size_t bytes, const void* data) {
    return gpu::createBuffer(GL_SHADER_STORAGE_BUFFER,
                             static_cast<GLsizeiptr>(std::max<std::size_t>(bytes, 4)), data,
                             GL_DYNAMIC_COPY);
}

// Copies and host writes must see the shaders' earlier writes (and not be overtaken by them):
// without GL_BUFFER_UPDATE_BARRIER_BIT a pool growth on the NVIDIA driver copied some bricks as
// they were before the last iteration, and the same run gave different masks (llvmpipe, which
// finishes each dispatch before the next command, never showed it).
void copyBuffer(const gpu::Buffer& from, const gpu::Buffer& to, std::size_t fromOffset,
                std::size_t toOffset, std::size_t bytes) {
    gpu::memoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
    glBindBuffer(GL_COPY_READ_BUFFER, from.id());
    glBindBuffer(GL_COPY_WRITE_BUFFER, to.id());
    glCopyBufferSubData(GL_COPY_READ_BUFFER, GL_COPY_WRITE_BUFFER,
                        static_cast<GLintptr>(fromOffset), static_cast<GLintptr>(toOffset),
                        static_cast<GLsizeiptr>(bytes));
}

} // namespace steerseg::solver::detail
