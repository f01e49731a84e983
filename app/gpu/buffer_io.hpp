#pragma once

// Host reads and writes of shader storage buffers that the compute passes also write, with the
// barriers that keep them in order with those passes.
#include "gpu/gl_handle.hpp"

#include <cstddef>
#include <string_view>
#include <vector>

namespace steerseg::gpu {

// Copies `bytes` at `offset` of the buffer into `out`, after every shader write issued before
// it; `what` names the buffer in the GlError thrown when it cannot be mapped.
void readBufferBytes(const Buffer& buffer, std::size_t offset, void* out, std::size_t bytes,
                     std::string_view what);

template <typename T>
std::vector<T> readBuffer(const Buffer& buffer, std::size_t count, std::string_view what) {
    std::vector<T> out(count);
    readBufferBytes(buffer, 0, out.data(), count * sizeof(T), what);
    return out;
}

// Writes `bytes` from `data` at `offset`, after (and never overtaken by) the shader writes
// issued before it.
void writeBuffer(const Buffer& buffer, std::size_t offset, const void* data, std::size_t bytes);

} // namespace steerseg::gpu
