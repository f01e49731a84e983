#pragma once

// The brick pool's storage buffers and the GPU copies between them (gpu_brick_pool*.cpp).
#include "gpu/gl_handle.hpp"

#include <cstddef>

namespace steerseg::solver::detail {

// A shader storage buffer of `bytes` (at least one word), uninitialised or from `data`.
[[nodiscard]] gpu::Buffer makeBuffer(std::size_t bytes, const void* data = nullptr);

// Copies `bytes` on the GPU after the shaders' earlier writes.
void copyBuffer(const gpu::Buffer& from, const gpu::Buffer& to, std::size_t fromOffset,
                std::size_t toOffset, std::size_t bytes);

} // namespace steerseg::solver::detail
