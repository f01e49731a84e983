#pragma once

#include <cstdint>
#include <glm/glm.hpp>

namespace steerseg::solver {

// The front's counters over one check interval (update_phi.comp's and measure_speed.comp's),
// read with the pool check: what the stop rules (SettleWatch, RunawayWatch) and a recorded
// series (tests/data/growth) are made of.
struct FrontCheck {
    int iteration = 0;        // iterations performed by the end of the interval
    float time = 0.0F;        // evolved time by then
    std::uint32_t gained = 0; // voxels that came inside during the interval
    std::uint32_t lost = 0;   // voxels that went outside
    std::uint32_t front = 0;  // the front's voxels in the interval's last iteration
    glm::ivec3 gainLo{0};     // box of the voxels that came inside (when gained > 0)
    glm::ivec3 gainHi{0};
    [[nodiscard]] std::int64_t net() const {
        return static_cast<std::int64_t>(gained) - static_cast<std::int64_t>(lost);
    }
};

} // namespace steerseg::solver
