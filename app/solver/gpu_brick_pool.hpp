#pragma once

#include "gpu/gl_handle.hpp"
#include "gpu/gpu_limits.hpp"
#include "solver/brick_pool_view.hpp"
#include "solver/control_block.hpp"

#include <cstddef>
#include <cstdint>
#include <glm/glm.hpp>
#include <span>
#include <string>
#include <vector>

namespace steerseg::solver::detail {

inline constexpr std::uint32_t kNoBrick = 0xFFFFFFFFu;

// The pool's level set copied on the GPU (undo, LevelSetCopy): the phi of every slot, the page
// table and the slot tables, which GpuBrickPool::restore puts back as they were.
struct PoolCopy {
    gpu::Buffer pageTable;
    gpu::Buffer phi;
    gpu::Buffer slotBrick;
    gpu::Buffer freeList; // its first freeCount words
    std::uint32_t capacity = 0;
    std::uint32_t freeCount = 0;
    std::size_t bytes = 0;
};

// Pool slots to hold `used` bricks plus a margin for the band's advance until the next check:
// what it grew over the last check (`growth`), the pending requests, and 1/16 of the band (a band
// that speeds up by more than that stalls once and is grown). Kept tight: with the shell scratch
// a slot costs 1.58 bricks of phi, so storage stays within 2x the used bricks only up to ~1.27
// slots per used brick.
inline std::uint32_t poolTarget(std::uint32_t used, std::uint32_t growth, std::uint32_t pending) {
    return used + used / 16 + growth + pending + 4;
}

// The sparse level-set storage on the GPU: page table, the phi pool, the per-slot shell scratch
// of the in-place step (shaders/solver/brick_shell.glsl), and the bookkeeping the passes share
// (slot -> brick, free list, active list, requests, states). phi is stored once: a step writes
// each brick's interior in place and only its shell (296 of 512 voxels at brick size 8) aside,
// 1.58x a brick where a second pool would be 2x.
// Capacity changes copy on the GPU; only a shrink reads the small slot map back to plan moves.
class GpuBrickPool {
  public:
    // Throws gpu::GpuCapacityError, naming the limit and the numbers, where the level set of
    // `dims` cannot be held or dispatched over within `limits` (docs/large-scans.md): the page
    // table past the storage block size, or more bricks than the 2D dispatches reach.
    GpuBrickPool(const glm::ivec3& dims, int brickSize, const gpu::GpuLimits& limits);

    // Replaces the level set by a dense phi (uniform bricks become constants), or by nothing
    // inside where `phi` is empty. `dense`: every
    // brick gets a slot (the dense benchmark mode). Resets the control block.
    void upload(std::span<const float> phi, bool dense);
    // Dense phi of the current buffer (tests, mask output; not per iteration), or of a copy.
    [[nodiscard]] std::vector<float> download() const;
    [[nodiscard]] std::vector<float> download(const PoolCopy& copy) const;
    // The inside mask (phi < 0) of the current buffer or of a copy, without a dense phi: a
    // quarter of the memory, and a constant brick's rows filled at once (the kiosk's autosave
    // reads it on the frame thread).
    [[nodiscard]] std::vector<std::uint8_t> downloadMask() const;
    [[nodiscard]] std::vector<std::uint8_t> downloadMask(const PoolCopy& copy) const;
    // Voxels inside (phi < 0), counted on the pool as it is stored: the page table and the
    // slots' phi read back, no dense phi built.
    [[nodiscard]] std::uint64_t countInside() const;

    // Copies the level set into new buffers on the GPU; `ctrl` must be fresh.
    [[nodiscard]] PoolCopy copy(const ControlBlock& ctrl) const;
    // Replaces the level set by a copy this pool took, as upload does (the slots' states are
    // unset until classify_bricks).
    void restore(const PoolCopy& copy);

    // Grows to newCapacity slots, copying on the GPU; `ctrl` must be fresh.
    void grow(std::uint32_t newCapacity, const ControlBlock& ctrl);
    // Moves used slots below newCapacity (GPU copies) and drops the rest.
    void shrink(std::uint32_t newCapacity, const ControlBlock& ctrl);

    void bind() const;
    // Every slot's speeds (solver/speed_cache.glsl) no longer hold: the speed, its parameters or
    // a barrier changed. The next pass over a brick computes them and its front again.
    void forgetSpeed();
    // Every slot's front must be measured again, from its phi (its sign rows no longer hold):
    // the level set changed outside a step.
    void forgetMeasures();

    [[nodiscard]] ControlBlock readControl() const;
    void writeControl(const ControlBlock& ctrl);

    [[nodiscard]] std::uint32_t capacity() const { return capacity_; }
    // Slots holding a brick, from a fresh control block.
    [[nodiscard]] std::uint32_t usedSlots(const ControlBlock& ctrl) const {
        return capacity_ - ctrl.freeCount;
    }
    // The most slots: every brick, or fewer where the phi pool would pass the storage block
    // size or the passes over the slots (64 per work group, 1D) the work group count.
    [[nodiscard]] std::uint32_t maxCapacity() const;
    // Which limit sets maxCapacity, with the numbers, for messages.
    [[nodiscard]] std::string capacityLimitText() const;
    [[nodiscard]] std::uint32_t brickCount() const { return brickCount_; }
    [[nodiscard]] std::size_t brickBytes() const;
    // Bytes of one slot's shell scratch.
    [[nodiscard]] std::size_t shellBytes() const;
    // The phi pool, the shell scratch and the page table.
    [[nodiscard]] std::size_t levelSetBytes() const;
    // Slot map, free, active, measure and band lists, states, fronts, requests and epochs.
    [[nodiscard]] std::size_t bookkeepingBytes() const;
    // What measure_speed keeps per slot (solver/speed_cache.glsl): a brick of speeds, a header
    // (the tag, the last side change, the last measure, the sign rows' validity) and the rows.
    [[nodiscard]] std::size_t speedBytes() const;
    [[nodiscard]] BrickPoolView view() const;
    [[nodiscard]] const glm::ivec3& brickGrid() const { return grid_; }
    [[nodiscard]] int brickSize() const { return brickSize_; }

  private:
    void allocateSlotBuffers(std::uint32_t capacity);
    void copySpeeds(const gpu::Buffer& old, std::uint32_t oldCapacity);
    [[nodiscard]] std::size_t speedSlotBytes() const;
    static constexpr std::uint32_t kSpeedHeaderWords = 4; // gpu_brick_pool_speed.cpp's runs
    // The control block of a pool just filled: nothing requested or active, `freeCount` free.
    void resetControl(std::uint32_t freeCount);
    [[nodiscard]] glm::ivec3 brickOrigin(std::uint32_t brick) const;
    // The grid of `pageTable` and `phi` as a dense volume of T: `inside` and `outside` for the
    // constant bricks, fromPhi(phi) for a stored brick's voxels; brick by brick, a row at a time.
    template <typename T, typename FromPhi>
    [[nodiscard]] std::vector<T> dense(const gpu::Buffer& pageTable, const gpu::Buffer& phi,
                                       std::uint32_t capacity, T inside, T outside,
                                       const FromPhi& fromPhi) const;

    glm::ivec3 dims_;
    glm::ivec3 grid_;
    int brickSize_;
    gpu::GpuLimits limits_;
    std::uint32_t brickCount_;
    std::uint32_t capacity_ = 0;
    gpu::Buffer pageTable_;
    gpu::Buffer phi_;
    gpu::Buffer shellNext_;
    gpu::Buffer control_;
    gpu::Buffer slotBrick_;
    gpu::Buffer freeList_;
    gpu::Buffer activeList_;
    gpu::Buffer requests_;
    gpu::Buffer wantEpoch_;
    gpu::Buffer slotState_;
    gpu::Buffer bandList_;
    gpu::Buffer slotFront_;  // two words per slot
    gpu::Buffer speedCache_; // the header's four runs of a word a slot, the speeds, the sign rows
};

} // namespace steerseg::solver::detail
