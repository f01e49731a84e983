#pragma once

#include "model/solver_types.hpp"
#include "solver/windowed_rate.hpp"

#include <cstdint>
#include <optional>

namespace steerseg::solver {

// What the solver measured over one check interval (update_phi.comp's counters).
struct GrowthSample {
    float time = 0.0F;    // evolved time at the end of the interval
    int iteration = 0;    // iterations performed by then
    std::int64_t net = 0; // voxels that came inside minus those that went outside
    bool anyGained = false;
    glm::ivec3 gainLo{0}; // box of the voxels that came inside (when anyGained)
    glm::ivec3 gainHi{0};
};

// Tells a leak from the front's growth rate: a front filling a structure grows, then slows as
// it reaches the boundary; one that broke through a narrow neck into tissue of the same
// intensity grows again, while its growth had fallen well below its peak. Pure (no GL), so the
// rule is tested on series. Thresholds, relative to the peak rate so that they hold for any
// scan size and speed scale:
// - slowed: the rate fell to kSlowedFraction of the peak or below;
// - floor: the lowest rate since, each taken over the last kFloorChecks calm checks (a slow
//   front gains a few voxels per check, and one quiet check among them is noise, not its pace:
//   the liver's threshold front, creeping at 20 +- 6 voxels a check, read one check of 8 as its
//   floor and tripped on its ordinary checks; tests/data/growth);
// - jump: after that, a rate of at least the floor plus kJumpFraction of the peak and at least
//   kJumpFactor times the floor, in kJumpChecks checks in a row (one noisy check is not a
//   leak).
class LeakWatch {
  public:
    static constexpr double kSlowedFraction = 0.2;
    static constexpr double kJumpFraction = 0.03;
    static constexpr double kJumpFactor = 3.0;
    static constexpr int kJumpChecks = 2;
    static constexpr int kWarmupChecks = 1; // a new seed's first check sets no peak
    static constexpr int kFloorChecks = 4;

    // The leak's site when this sample completes a jump, else nothing.
    std::optional<model::LeakSite> observe(const GrowthSample& sample);
    // After an edit or a parameter change: the growth that follows is the operator's doing.
    void reset();
    [[nodiscard]] double lastRate() const { return lastRate_; }

  private:
    int samples_ = 0;
    bool said_ = false;
    bool haveTime_ = false;
    float lastTime_ = 0.0F;
    double lastRate_ = 0.0;
    double peak_ = 0.0;
    bool slowed_ = false;
    double floor_ = 0.0;
    // The calm checks since the slowdown: net voxels over evolved time.
    WindowedRate<kFloorChecks> calm_;
    int jumpRun_ = 0;
    bool haveBox_ = false;
    glm::ivec3 boxLo_{0};
    glm::ivec3 boxHi_{0};
};

} // namespace steerseg::solver
