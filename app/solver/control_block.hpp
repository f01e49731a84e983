#pragma once

#include <cstddef>
#include <cstdint>

namespace steerseg::solver::detail {

// Host mirror of solver_common.glsl's Control block (std430, 4-byte members).
struct ControlBlock {
    std::uint32_t allocArgs[3];
    std::uint32_t brickArgs[3];
    std::uint32_t settleArgs[3];
    std::uint32_t requestCount;
    std::uint32_t activeCount;
    std::uint32_t freeCount;
    std::uint32_t popped;
    std::uint32_t stalled;
    std::uint32_t maxRateBits;
    float dt;
    float time;
    std::uint32_t iteration;
    std::uint32_t lastChange;
    float lastChangeTime;
    std::uint32_t peakActive;
    std::uint32_t gained;
    std::uint32_t lost;
    std::uint32_t gainLo[3];
    std::uint32_t gainHi[3];
    std::uint32_t bandCount;     // used slots, asleep or awake
    std::uint32_t visitedBricks; // active bricks summed over the steps since the host cleared it
    std::uint32_t frontVoxels;   // the front's voxels in the iteration under way
    std::uint32_t groupsDone;    // work groups of the pass under way that finished
    // The last iteration's (or edit's) activeCount, bandCount and frontVoxels: settle_bricks
    // clears the working counters for the next iteration before the host reads the block.
    std::uint32_t shownActive;
    std::uint32_t shownBand;
    std::uint32_t shownFront;
    std::uint32_t measureCount;   // active bricks whose front measure_speed measures
    std::uint32_t measureArgs[3]; // its indirect dispatch
};
static_assert(sizeof(ControlBlock) == 40 * 4);

// Clears the leak watch's counters (update_phi.comp accumulates them between checks).
inline void clearGrowth(ControlBlock& ctrl) {
    ctrl.gained = 0;
    ctrl.lost = 0;
    for (int a = 0; a < 3; ++a) {
        ctrl.gainLo[a] = 0xFFFFFFFFU;
        ctrl.gainHi[a] = 0;
    }
}

// Byte offsets of the indirect dispatch arguments in the control block.
inline constexpr std::ptrdiff_t kAllocArgs = 0;
inline constexpr std::ptrdiff_t kBrickArgs = 12;
inline constexpr std::ptrdiff_t kSettleArgs = 24;
inline constexpr std::ptrdiff_t kMeasureArgs = 37 * 4;
static_assert(kMeasureArgs == offsetof(ControlBlock, measureArgs));

// Work groups per row of the passes laid out 2D over requested or active bricks (one group a
// brick): solver_common.glsl's GROUPS_PER_ROW.
inline constexpr std::uint32_t kGroupsPerRow = 1024;
// Slots (or active bricks) per work group of the 1D passes over them (build_active_list's and
// the list passes' local size).
inline constexpr std::uint32_t kSlotsPerGroup = 64;

// Work groups of `size` invocations that cover `count` items.
inline std::uint32_t groupsOf(std::uint32_t count, std::uint32_t size) {
    return (count + size - 1) / size;
}

} // namespace steerseg::solver::detail
