#include "solver/gpu_brick_pool.hpp"

#include "common/bindings.h"
#include "core/volume.hpp"
#include "gpu/buffer_io.hpp"
#include "gpu/gl_error.hpp"
#include "model/level_set_params.hpp"
#include "solver/control_block.hpp"
#include "solver/pool_buffers.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <stdexcept>
#include <string>

namespace steerseg::solver::detail {

namespace {

constexpr std::uint32_t kMinCapacity = 16;

} // namespace

GpuBrickPool::GpuBrickPool(const glm::ivec3& dims, int brickSize, const gpu::GpuLimits& limits)
    : dims_(dims), grid_((dims + brickSize - 1) / brickSize), brickSize_(brickSize),
      limits_(limits), brickCount_(static_cast<std::uint32_t>(grid_.x * grid_.y * grid_.z)) {
    const std::string levelSet = "level set of " + gpu::sizeText(dims.x, dims.y, dims.z) + " (" +
                                 std::to_string(brickCount_) + " bricks of " +
                                 std::to_string(brickSize) + "^3)";
    const std::size_t block = limits_.maxShaderStorageBlockBytes;
    if (static_cast<std::size_t>(brickCount_) * 4 > block || block < brickBytes()) {
        throw gpu::GpuCapacityError(levelSet + ": its page table (" +
                                    gpu::bytesText(brickCount_ * 4.0) +
                                    ") exceeds GL_MAX_SHADER_STORAGE_BLOCK_SIZE " +
                                    gpu::bytesText(static_cast<double>(block)) + " of this GPU");
    }
    // Passes over requested bricks run one work group per brick, kGroupsPerRow to a row.
    const std::uint32_t rows = groupsOf(brickCount_, kGroupsPerRow);
    if (rows > limits_.maxComputeWorkGroupCount[1] ||
        kGroupsPerRow > limits_.maxComputeWorkGroupCount[0]) {
        throw gpu::GpuCapacityError(
            levelSet + ": one work group per brick needs " + std::to_string(rows) + " rows of " +
            std::to_string(kGroupsPerRow) + ", more than GL_MAX_COMPUTE_WORK_GROUP_COUNT " +
            std::to_string(limits_.maxComputeWorkGroupCount[0]) + "x" +
            std::to_string(limits_.maxComputeWorkGroupCount[1]) + " of this GPU");
    }
    // A sphere edit runs one work group per brick of its box in each axis.
    for (int a = 0; a < 3; ++a) {
        if (static_cast<std::uint32_t>(grid_[a]) > limits_.maxComputeWorkGroupCount[a]) {
            throw gpu::GpuCapacityError(
                levelSet + ": " + std::to_string(grid_[a]) + " bricks along axis " +
                std::to_string(a) + " exceed GL_MAX_COMPUTE_WORK_GROUP_COUNT[" + std::to_string(a) +
                "] " + std::to_string(limits_.maxComputeWorkGroupCount[a]) + " of this GPU");
        }
    }
    const std::vector<std::uint32_t> outside(brickCount_, kBrickOutside);
    pageTable_ = makeBuffer(brickCount_ * 4, outside.data());
    requests_ = makeBuffer(brickCount_ * 4);
    const std::vector<std::uint32_t> zeros(brickCount_, 0);
    wantEpoch_ = makeBuffer(brickCount_ * 4, zeros.data());
    ControlBlock ctrl{};
    clearGrowth(ctrl);
    control_ = makeBuffer(sizeof ctrl, &ctrl);
}

std::size_t GpuBrickPool::brickBytes() const {
    const auto b = static_cast<std::size_t>(brickSize_);
    return b * b * b * sizeof(float);
}

std::size_t GpuBrickPool::shellBytes() const {
    const auto b = static_cast<std::size_t>(brickSize_);
    return (b * b * b - (b - 2) * (b - 2) * (b - 2)) * sizeof(float);
}

// The speed cache is the largest buffer over the slots: a brick of speeds and a header each.
std::uint32_t GpuBrickPool::maxCapacity() const {
    return static_cast<std::uint32_t>(std::min<std::size_t>(
        {brickCount_, limits_.maxShaderStorageBlockBytes / speedSlotBytes(),
         static_cast<std::size_t>(limits_.maxComputeWorkGroupCount[0]) * kSlotsPerGroup}));
}

std::string GpuBrickPool::capacityLimitText() const {
    const std::uint32_t most = maxCapacity();
    const std::string bricks = std::to_string(most) + " bricks";
    if (most == brickCount_) {
        return "every brick of the volume (" + bricks + ")";
    }
    if (most == limits_.maxShaderStorageBlockBytes / speedSlotBytes()) {
        return bricks + " (" + gpu::bytesText(static_cast<double>(most) * speedSlotBytes()) +
               " of their kept speeds), the most GL_MAX_SHADER_STORAGE_BLOCK_SIZE " +
               gpu::bytesText(static_cast<double>(limits_.maxShaderStorageBlockBytes)) +
               " of this GPU holds";
    }
    return bricks + ", the most GL_MAX_COMPUTE_WORK_GROUP_COUNT[0] " +
           std::to_string(limits_.maxComputeWorkGroupCount[0]) + " of this GPU reaches at " +
           std::to_string(kSlotsPerGroup) + " slots per work group";
}

std::size_t GpuBrickPool::levelSetBytes() const {
    return static_cast<std::size_t>(capacity_) * (brickBytes() + shellBytes()) +
           static_cast<std::size_t>(brickCount_) * 4;
}

std::size_t GpuBrickPool::bookkeepingBytes() const {
    return static_cast<std::size_t>(capacity_) * 4 * 8 +
           static_cast<std::size_t>(brickCount_) * 4 * 2 + sizeof(ControlBlock);
}

void GpuBrickPool::allocateSlotBuffers(std::uint32_t capacity) {
    capacity_ = capacity;
    phi_ = makeBuffer(capacity * brickBytes());
    shellNext_ = makeBuffer(capacity * shellBytes());
    slotBrick_ = makeBuffer(capacity * 4);
    freeList_ = makeBuffer(capacity * 4);
    activeList_ = makeBuffer(capacity * 8); // the active list, then the measure list
    slotState_ = makeBuffer(capacity * 4);
    bandList_ = makeBuffer(capacity * 4);
    slotFront_ = makeBuffer(capacity * 8);
    speedCache_ = makeBuffer(capacity * speedSlotBytes());
    forgetSpeed(); // the speeds themselves are written before they are read
}

void GpuBrickPool::upload(std::span<const float> phi, bool dense) {
    const int b = brickSize_;
    const std::size_t bv = brickBytes() / sizeof(float);
    const std::size_t voxels = static_cast<std::size_t>(dims_.x) *
                               static_cast<std::size_t>(dims_.y) *
                               static_cast<std::size_t>(dims_.z);
    if (!phi.empty() && phi.size() != voxels) {
        throw std::invalid_argument("brick pool: phi does not match the volume's dimensions");
    }
    // Empty: everything outside, without a dense phi on the host (1 GiB at 512x512x1000).
    const bool outside = phi.empty();
    auto at = [&](int i, int j, int k) {
        if (outside) {
            return model::kPhiFar;
        }
        i = std::min(i, dims_.x - 1);
        j = std::min(j, dims_.y - 1);
        k = std::min(k, dims_.z - 1);
        return phi[linearIndex(dims_, i, j, k)];
    };
    std::vector<std::uint32_t> page(brickCount_, kBrickOutside);
    std::vector<std::uint32_t> usedBricks;
    for (std::uint32_t n = 0; n < brickCount_; ++n) {
        const glm::ivec3 o = brickOrigin(n);
        bool negative = false;
        bool positive = false;
        bool live = false;
        if (!outside) {
            for (int k = o.z; k < std::min(o.z + b, dims_.z); ++k) {
                for (int j = o.y; j < std::min(o.y + b, dims_.y); ++j) {
                    for (int i = o.x; i < std::min(o.x + b, dims_.x); ++i) {
                        const float p = at(i, j, k);
                        live = live || std::abs(p) < model::kPhiFar;
                        negative = negative || p < 0.0F;
                        positive = positive || p >= 0.0F;
                    }
                }
            }
        }
        if (dense || live || (negative && positive)) {
            page[n] = static_cast<std::uint32_t>(usedBricks.size());
            usedBricks.push_back(n);
        } else {
            page[n] = negative ? kBrickInside : kBrickOutside;
        }
    }
    const auto used = static_cast<std::uint32_t>(usedBricks.size());
    if (used > maxCapacity()) {
        throw gpu::GpuCapacityError("the level set needs " + std::to_string(used) +
                                    " bricks, more than " + capacityLimitText());
    }
    const std::uint32_t capacity =
        dense ? brickCount_
              : std::min(maxCapacity(), std::max(kMinCapacity, poolTarget(used, 0, 0)));
    allocateSlotBuffers(capacity);

    std::vector<float> pool(static_cast<std::size_t>(capacity) * bv, model::kPhiFar);
    std::vector<std::uint32_t> slotBrick(capacity, kNoBrick);
    for (std::uint32_t s = 0; s < used; ++s) {
        const std::uint32_t n = usedBricks[s];
        slotBrick[s] = n;
        const glm::ivec3 o = brickOrigin(n);
        std::size_t v = s * bv;
        for (int k = 0; k < b; ++k) {
            for (int j = 0; j < b; ++j) {
                for (int i = 0; i < b; ++i) {
                    pool[v++] = at(o.x + i, o.y + j, o.z + k);
                }
            }
        }
    }
    std::vector<std::uint32_t> freeList;
    for (std::uint32_t s = capacity; s > used; --s) {
        freeList.push_back(s - 1);
    }
    gpu::writeBuffer(phi_, 0, pool.data(), pool.size() * sizeof(float));
    gpu::writeBuffer(slotBrick_, 0, slotBrick.data(), slotBrick.size() * 4);
    gpu::writeBuffer(freeList_, 0, freeList.data(), freeList.size() * 4);
    gpu::writeBuffer(pageTable_, 0, page.data(), page.size() * 4);
    resetControl(capacity - used);
    gpu::checkGl("uploading the level set");
}

glm::ivec3 GpuBrickPool::brickOrigin(std::uint32_t brick) const {
    const auto n = static_cast<int>(brick);
    return glm::ivec3(n % grid_.x, (n / grid_.x) % grid_.y, n / (grid_.x * grid_.y)) * brickSize_;
}

void GpuBrickPool::resetControl(std::uint32_t freeCount) {
    ControlBlock ctrl = readControl();
    ctrl.requestCount = 0;
    ctrl.activeCount = 0;
    ctrl.popped = 0;
    ctrl.stalled = 0;
    ctrl.groupsDone = 0;
    ctrl.freeCount = freeCount;
    writeControl(ctrl);
}

PoolCopy GpuBrickPool::copy(const ControlBlock& ctrl) const {
    PoolCopy c;
    c.capacity = capacity_;
    c.freeCount = ctrl.freeCount;
    const std::size_t phiBytes = capacity_ * brickBytes();
    c.pageTable = makeBuffer(brickCount_ * 4);
    c.phi = makeBuffer(phiBytes);
    c.slotBrick = makeBuffer(capacity_ * 4);
    c.freeList = makeBuffer(c.freeCount * 4);
    copyBuffer(pageTable_, c.pageTable, 0, 0, brickCount_ * 4);
    copyBuffer(phi_, c.phi, 0, 0, phiBytes);
    copyBuffer(slotBrick_, c.slotBrick, 0, 0, capacity_ * 4);
    if (c.freeCount > 0) {
        copyBuffer(freeList_, c.freeList, 0, 0, c.freeCount * 4);
    }
    c.bytes = phiBytes + (brickCount_ + capacity_ + c.freeCount) * std::size_t{4};
    gpu::checkGl("copying the level set");
    return c;
}

void GpuBrickPool::restore(const PoolCopy& c) {
    allocateSlotBuffers(c.capacity);
    copyBuffer(c.pageTable, pageTable_, 0, 0, brickCount_ * 4);
    copyBuffer(c.phi, phi_, 0, 0, c.capacity * brickBytes());
    copyBuffer(c.slotBrick, slotBrick_, 0, 0, c.capacity * 4);
    if (c.freeCount > 0) {
        copyBuffer(c.freeList, freeList_, 0, 0, c.freeCount * 4);
    }
    resetControl(c.freeCount);
    gpu::checkGl("restoring the level set");
}

void GpuBrickPool::grow(std::uint32_t newCapacity, const ControlBlock& ctrl) {
    newCapacity = std::min(newCapacity, maxCapacity());
    if (newCapacity <= capacity_) {
        return;
    }
    const std::uint32_t old = capacity_;
    gpu::Buffer oldPhi = std::move(phi_);
    gpu::Buffer oldSlotBrick = std::move(slotBrick_);
    gpu::Buffer oldFree = std::move(freeList_);
    gpu::Buffer oldState = std::move(slotState_);
    gpu::Buffer oldFront = std::move(slotFront_);
    gpu::Buffer oldSpeed = std::move(speedCache_);
    allocateSlotBuffers(newCapacity);
    copySpeeds(oldSpeed, old);
    copyBuffer(oldPhi, phi_, 0, 0, old * brickBytes());
    copyBuffer(oldSlotBrick, slotBrick_, 0, 0, old * 4);
    copyBuffer(oldState, slotState_, 0, 0, old * 4);
    copyBuffer(oldFront, slotFront_, 0, 0, old * 8); // a sleeping brick's time-step bound
    copyBuffer(oldFree, freeList_, 0, 0, ctrl.freeCount * 4);
    const std::vector<std::uint32_t> none(newCapacity - old, kNoBrick);
    gpu::writeBuffer(slotBrick_, old * 4, none.data(), none.size() * 4);
    std::vector<std::uint32_t> added;
    for (std::uint32_t s = newCapacity; s > old; --s) {
        added.push_back(s - 1);
    }
    gpu::writeBuffer(freeList_, ctrl.freeCount * 4, added.data(), added.size() * 4);
    ControlBlock next = ctrl;
    next.freeCount += static_cast<std::uint32_t>(added.size());
    next.stalled = 0;
    writeControl(next);
    gpu::checkGl("growing the brick pool");
}

void GpuBrickPool::shrink(std::uint32_t newCapacity, const ControlBlock& ctrl) {
    const std::uint32_t used = usedSlots(ctrl);
    newCapacity = std::max({newCapacity, used, kMinCapacity});
    if (newCapacity >= capacity_) {
        return;
    }
    // Plan on the CPU from the small slot map; the bricks themselves move on the GPU.
    auto slotBrick = gpu::readBuffer<std::uint32_t>(slotBrick_, capacity_, "a solver buffer");
    auto state = gpu::readBuffer<std::uint32_t>(slotState_, capacity_,
                                                "a solver buffer"); // sleep bits move with it
    auto front = gpu::readBuffer<std::uint32_t>(slotFront_, 2 * static_cast<std::size_t>(capacity_),
                                                "a solver buffer");
    auto page = gpu::readBuffer<std::uint32_t>(pageTable_, brickCount_, "a solver buffer");
    std::vector<std::uint32_t> lowFree;
    for (std::uint32_t s = 0; s < newCapacity; ++s) {
        if (slotBrick[s] == kNoBrick) {
            lowFree.push_back(s);
        }
    }
    std::size_t nextFree = 0;
    for (std::uint32_t s = newCapacity; s < capacity_; ++s) {
        if (slotBrick[s] == kNoBrick) {
            continue;
        }
        const std::uint32_t to = lowFree[nextFree++];
        copyBuffer(phi_, phi_, s * brickBytes(), to * brickBytes(), brickBytes());
        slotBrick[to] = slotBrick[s];
        state[to] = state[s];
        front[2 * to] = front[2 * s];
        front[2 * to + 1] = front[2 * s + 1];
        page[slotBrick[s]] = to;
    }
    std::vector<std::uint32_t> freeList(lowFree.begin() + static_cast<std::ptrdiff_t>(nextFree),
                                        lowFree.end());
    gpu::Buffer oldPhi = std::move(phi_);
    gpu::Buffer oldSpeed = std::move(speedCache_);
    const std::uint32_t oldCapacity = capacity_;
    allocateSlotBuffers(newCapacity);
    copyBuffer(oldPhi, phi_, 0, 0, newCapacity * brickBytes());
    copySpeeds(oldSpeed, oldCapacity); // a moved brick's tag stays behind: computed again
    gpu::writeBuffer(slotBrick_, 0, slotBrick.data(), newCapacity * 4);
    gpu::writeBuffer(slotState_, 0, state.data(), newCapacity * 4);
    gpu::writeBuffer(slotFront_, 0, front.data(), newCapacity * 8);
    gpu::writeBuffer(freeList_, 0, freeList.data(), freeList.size() * 4);
    gpu::writeBuffer(pageTable_, 0, page.data(), page.size() * 4);
    ControlBlock next = ctrl;
    next.freeCount = static_cast<std::uint32_t>(freeList.size());
    writeControl(next);
    gpu::checkGl("shrinking the brick pool");
}

void GpuBrickPool::bind() const {
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, PAGE_TABLE_BINDING, pageTable_.id());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, PHI_POOL_BINDING, phi_.id());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, SHELL_NEXT_BINDING, shellNext_.id());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, CONTROL_BINDING, control_.id());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, SLOT_BRICK_BINDING, slotBrick_.id());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, FREE_LIST_BINDING, freeList_.id());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, ACTIVE_LIST_BINDING, activeList_.id());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, REQUESTS_BINDING, requests_.id());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, WANT_EPOCH_BINDING, wantEpoch_.id());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, SLOT_STATE_BINDING, slotState_.id());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, BAND_LIST_BINDING, bandList_.id());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, SLOT_FRONT_BINDING, slotFront_.id());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, SPEED_CACHE_BINDING, speedCache_.id());
    glBindBuffer(GL_DISPATCH_INDIRECT_BUFFER, control_.id());
}

ControlBlock GpuBrickPool::readControl() const {
    const auto words =
        gpu::readBuffer<std::uint32_t>(control_, sizeof(ControlBlock) / 4, "a solver buffer");
    ControlBlock ctrl{};
    std::memcpy(&ctrl, words.data(), sizeof ctrl);
    return ctrl;
}

void GpuBrickPool::writeControl(const ControlBlock& ctrl) {
    gpu::writeBuffer(control_, 0, &ctrl, sizeof ctrl);
}

BrickPoolView GpuBrickPool::view() const {
    BrickPoolView v;
    v.pageTableBuffer = pageTable_.id();
    v.phiPoolBuffer = phi_.id();
    v.volumeDims = dims_;
    v.brickGrid = grid_;
    v.brickSize = brickSize_;
    v.phiFar = model::kPhiFar;
    return v;
}

} // namespace steerseg::solver::detail
