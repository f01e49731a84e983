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

template <typename T, typename FromPhi>
std::vector<T> GpuBrickPool::dense(const gpu::Buffer& pageTable, const gpu::Buffer& phiPool,
                                   std::uint32_t capacity, T inside, T outside,
                                   const FromPhi& fromPhi) const {
    const auto page = gpu::readBuffer<std::uint32_t>(pageTable, brickCount_, "a solver buffer");
    const std::size_t bv = brickBytes() / sizeof(float);
    const auto pool = gpu::readBuffer<float>(phiPool, capacity * bv, "a solver buffer");
    std::vector<T> out(static_cast<std::size_t>(dims_.x) * static_cast<std::size_t>(dims_.y) *
                       static_cast<std::size_t>(dims_.z));
    const int b = brickSize_;
    for (std::uint32_t n = 0; n < brickCount_; ++n) {
        // A brick on the far faces reaches past the scan: only its voxels inside are written.
        const glm::ivec3 o = brickOrigin(n);
        const glm::ivec3 extent = glm::min(o + b, dims_) - o;
        const std::uint32_t slot = page[n];
        for (int k = 0; k < extent.z; ++k) {
            for (int j = 0; j < extent.y; ++j) {
                T* row = out.data() + linearIndex(dims_, o.x, o.y + j, o.z + k);
                if (slot == kBrickInside || slot == kBrickOutside) {
                    std::fill(row, row + extent.x, slot == kBrickInside ? inside : outside);
                    continue;
                }
                const float* from =
                    pool.data() + slot * bv + static_cast<std::size_t>(b * (j + b * k));
                std::transform(from, from + extent.x, row, fromPhi);
            }
        }
    }
    return out;
}

namespace {
float asIs(float phi) {
    return phi;
}
std::uint8_t isInside(float phi) {
    return static_cast<std::uint8_t>(phi < 0.0F);
}
} // namespace

std::vector<float> GpuBrickPool::download() const {
    return dense(pageTable_, phi_, capacity_, -model::kPhiFar, model::kPhiFar, asIs);
}

std::vector<float> GpuBrickPool::download(const PoolCopy& copy) const {
    return dense(copy.pageTable, copy.phi, copy.capacity, -model::kPhiFar, model::kPhiFar, asIs);
}

std::vector<std::uint8_t> GpuBrickPool::downloadMask() const {
    return dense(pageTable_, phi_, capacity_, std::uint8_t{1}, std::uint8_t{0}, isInside);
}

std::vector<std::uint8_t> GpuBrickPool::downloadMask(const PoolCopy& copy) const {
    return dense(copy.pageTable, copy.phi, copy.capacity, std::uint8_t{1}, std::uint8_t{0},
                 isInside);
}

} // namespace steerseg::solver::detail
