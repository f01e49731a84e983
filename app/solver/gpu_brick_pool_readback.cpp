// The pool read back to the host: dense phi (mask output, undo's copies moved to host memory,
// tests) and the inside count, never per iteration.
#include "core/volume.hpp"
#include "gpu/buffer_io.hpp"
#include "model/level_set_params.hpp"
#include "solver/gpu_brick_pool.hpp"

#include <algorithm>
#include <cstddef>

namespace steerseg::solver::detail {

std::uint64_t GpuBrickPool::countInside() const {
    const auto page = gpu::readBuffer<std::uint32_t>(pageTable_, brickCount_, "a solver buffer");
    const std::size_t bv = brickBytes() / sizeof(float);
    const auto pool = gpu::readBuffer<float>(phi_, capacity_ * bv, "a solver buffer");
    const int b = brickSize_;
    std::uint64_t inside = 0;
    for (std::uint32_t n = 0; n < brickCount_; ++n) {
        if (page[n] == kBrickOutside) {
            continue;
        }
        // A brick on the far faces reaches past the scan: only its voxels inside count.
        const glm::ivec3 o = brickOrigin(n);
        const glm::ivec3 extent = glm::min(o + b, dims_) - o;
        if (page[n] == kBrickInside) {
            inside += static_cast<std::uint64_t>(extent.x) * static_cast<std::uint64_t>(extent.y) *
                      static_cast<std::uint64_t>(extent.z);
            continue;
        }
        const float* brick = pool.data() + page[n] * bv;
        for (int k = 0; k < extent.z; ++k) {
            for (int j = 0; j < extent.y; ++j) {
                const float* row = brick + static_cast<std::ptrdiff_t>(b * (j + b * k));
                inside += static_cast<std::uint64_t>(
                    std::count_if(row, row + extent.x, [](float p) { return p < 0.0F; }));
            }
        }
    }
    return inside;
}

std::vector<float> GpuBrickPool::download() const {
    return densePhi(pageTable_, phi_, capacity_);
}

std::vector<float> GpuBrickPool::download(const PoolCopy& copy) const {
    return densePhi(copy.pageTable, copy.phi, copy.capacity);
}

std::vector<float> GpuBrickPool::densePhi(const gpu::Buffer& pageTable, const gpu::Buffer& phiPool,
                                          std::uint32_t capacity) const {
    const auto page = gpu::readBuffer<std::uint32_t>(pageTable, brickCount_, "a solver buffer");
    const std::size_t bv = brickBytes() / sizeof(float);
    const auto pool = gpu::readBuffer<float>(phiPool, capacity * bv, "a solver buffer");
    std::vector<float> phi(static_cast<std::size_t>(dims_.x) * static_cast<std::size_t>(dims_.y) *
                           static_cast<std::size_t>(dims_.z));
    const int b = brickSize_;
    for (int k = 0; k < dims_.z; ++k) {
        for (int j = 0; j < dims_.y; ++j) {
            for (int i = 0; i < dims_.x; ++i) {
                const auto brick =
                    static_cast<std::size_t>(i / b + grid_.x * (j / b + grid_.y * (k / b)));
                const std::uint32_t slot = page[brick];
                float value = model::kPhiFar;
                if (slot == kBrickInside) {
                    value = -model::kPhiFar;
                } else if (slot != kBrickOutside) {
                    value = pool[slot * bv +
                                 static_cast<std::size_t>(i % b + b * (j % b + b * (k % b)))];
                }
                phi[linearIndex(dims_, i, j, k)] = value;
            }
        }
    }
    return phi;
}

} // namespace steerseg::solver::detail
