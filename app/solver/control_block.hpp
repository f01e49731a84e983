#pragma once

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

} // namespace steerseg::solver::detail
