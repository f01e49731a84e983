#pragma once

#include "model/solver_types.hpp"
#include "solver/front_check.hpp"
#include "solver/windowed_rate.hpp"

#include <cstdint>
#include <optional>

namespace steerseg::solver {

// Tells a runaway fill from the growth of a structure, where LeakWatch's jump never comes: a
// front that spills into tissue of the same intensity along a wide contact grows on without
// ever slowing and speeding up again. What gives it away is that after most of its front has
// stopped it adds more than the structure could hold, and does so without slowing down, while
// the fill of a bounded structure slows as it nears completion. Pure (no GL), tested on series.
//
// - Slowed: the front's mean speed over a check, the net voxels gained per front voxel and
//   iteration (its mean displacement per step), fell to kSlowedFraction of its peak or below:
//   most of the front has stopped at an edge. The peak is taken from the second check on (a new
//   seed's first interval holds its start).
// - Rate: the net voxels gained per iteration over the last kRateChecks checks (one check is
//   noise); over the slowdown's check and the next kRateChecks - 1 it is the reference.
// - Bound: at the slowdown, the front's F voxels (both sides of the surface) bound about F / 2
//   voxel faces, and no body with a surface of A faces holds more than the ball with that
//   surface, A^(3/2) / (6 sqrt(pi)) voxels (the isoperimetric inequality). A structure cut by
//   the scan's border has surface there that is no front, so this is a size, not a strict
//   bound: the liver's front filled 4x it after slowing (tests/data/growth), but its rate fell.
// - Runaway: the net voxels gained since the slowdown exceed `factor` times the bound (2 by
//   default, model::SolverOptions::runawayFactor, which says why) while the rate is at least the
//   reference: the fill added more than a body of that front holds and did not slow doing so. Its
//   site is the box of the voxels that came inside since the slowdown.
// Every quantity is in voxels and iterations: the rule holds for any speed's units (the time
// step makes the fastest front voxel move half a voxel a step) and any structure's size.
class RunawayWatch {
  public:
    static constexpr double kSlowedFraction = 0.2;
    static constexpr int kRateChecks = 4;

    explicit RunawayWatch(double factor) : factor_(factor) {}

    std::optional<model::LeakSite> observe(const FrontCheck& check);
    // After an edit or a parameter change: the growth that follows is the operator's doing.
    void reset();
    // The net voxels gained since the slowdown over the bound (0 before a slowdown).
    [[nodiscard]] double lastRatio() const { return ratio_; }

  private:
    double factor_;
    bool started_ = false;
    int lastIteration_ = 0;
    int checks_ = 0;
    double peak_ = 0.0;
    bool slowed_ = false;
    bool said_ = false;
    double bound_ = 0.0;
    std::int64_t since_ = 0; // net voxels gained since the slowdown
    double ratio_ = 0.0;
    // The checks since the slowdown: net voxels per iteration.
    WindowedRate<kRateChecks> recent_;
    double reference_ = 0.0; // the rate from the slowdown on
    bool haveBox_ = false;
    glm::ivec3 boxLo_{0};
    glm::ivec3 boxHi_{0};
};

} // namespace steerseg::solver
