#pragma once

#include <cstddef>
#include <cstdint>

namespace steerseg::solver::detail {

// Host mirror of solver_common.glsl's Control block (std430, 4-byte members).
struct ControlBlock {
    std::uint32_t allocArgs[3];
    std::uint32_t brickArgs[3];
    std::uint32_t listArgs[3];
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
};
static_assert(sizeof(ControlBlock) == 21 * 4);

// Byte offsets of the indirect dispatch arguments in the control block.
inline constexpr std::ptrdiff_t kAllocArgs = 0;
inline constexpr std::ptrdiff_t kBrickArgs = 12;
inline constexpr std::ptrdiff_t kListArgs = 24;

// Work groups of `size` invocations that cover `count` items.
inline std::uint32_t groupsOf(std::uint32_t count, std::uint32_t size) {
    return (count + size - 1) / size;
}

} // namespace steerseg::solver::detail
