// What measure_speed keeps per slot between steps (shaders/solver/speed_cache.glsl, whose
// layout this mirrors): a header of four runs of one word a slot, then each slot's speeds, then
// each slot's sign rows.
#include "gpu/buffer_io.hpp"
#include "solver/gpu_brick_pool.hpp"
#include "solver/pool_buffers.hpp"

#include <algorithm>
#include <vector>

namespace steerseg::solver::detail {

namespace {

// The header's runs, in order: the brick whose speeds a slot holds, the step after which one
// of its voxels last changed side, the step at which measure_speed last measured it, whether
// its sign rows hold its phi's signs.
constexpr std::size_t kTagRun = 0;
constexpr std::size_t kSideChangeRun = 1;
constexpr std::size_t kMeasureRun = 2;
constexpr std::size_t kSignsRun = 3;
static_assert(kSignsRun == kMeasureRun + 1, "forgetMeasures clears the two runs at once");

} // namespace

std::size_t GpuBrickPool::speedSlotBytes() const {
    const auto b = static_cast<std::size_t>(brickSize_);
    return brickBytes() + kSpeedHeaderWords * 4 + b * b * 4; // speeds, header, sign rows
}

std::size_t GpuBrickPool::speedBytes() const {
    return static_cast<std::size_t>(capacity_) * speedSlotBytes();
}

void GpuBrickPool::forgetSpeed() {
    const std::vector<std::uint32_t> none(std::size_t{kSpeedHeaderWords} * capacity_, 0);
    gpu::writeBuffer(speedCache_, 0, none.data(), none.size() * 4);
}

// The sign rows go with the measures: both stand for phi as the last step left it.
void GpuBrickPool::forgetMeasures() {
    const std::vector<std::uint32_t> never(2 * std::size_t{capacity_}, 0);
    gpu::writeBuffer(speedCache_, kMeasureRun * capacity_ * 4, never.data(), never.size() * 4);
}

// The tags, side changes and speeds of the slots both the old cache (of oldCapacity slots) and
// the current one have; each run's offset follows the capacity. The measures and the sign rows
// are not kept: every brick is measured again, from its phi.
void GpuBrickPool::copySpeeds(const gpu::Buffer& old, std::uint32_t oldCapacity) {
    const std::size_t kept = std::min(oldCapacity, capacity_);
    const std::size_t was = oldCapacity * std::size_t{4};
    const std::size_t now = capacity_ * std::size_t{4};
    for (const std::size_t run : {kTagRun, kSideChangeRun}) {
        copyBuffer(old, speedCache_, run * was, run * now, kept * 4);
    }
    copyBuffer(old, speedCache_, kSpeedHeaderWords * was, kSpeedHeaderWords * now,
               kept * brickBytes());
}

} // namespace steerseg::solver::detail
