#pragma once

#include "model/solver_types.hpp"
#include "solver/front_check.hpp"

#include <cstdint>
#include <optional>

namespace steerseg::solver {

// Tells a runaway fill from the growth of a structure, where LeakWatch's jump never comes: a
// front that spills into tissue of the same intensity along a wide contact grows on without
// ever slowing and speeding up again. What gives it away is the volume it adds after most of
// its front has stopped. Pure (no GL), tested on series.
//
// - Slowed: the front's mean speed (net voxels gained per front voxel and iteration, i.e. its
//   mean displacement per step) fell to kSlowedFraction of its peak or below: most of the front
//   has reached the structure's edge. The peak is taken from the second check on (a new seed's
//   first interval holds its start).
// - Bound: at that check, the front F voxels (both sides of the surface) bound a surface of
//   about F / 2 voxel faces, and no body with a surface of area A holds more than a ball with
//   that area, A^(3/2) / (6 sqrt(pi)) voxels (the isoperimetric inequality): whatever the
//   structure's shape, that is the most it can hold.
// - Runaway: the net voxels gained since the slowdown exceed `factor` times that bound (1 by
//   default, model::SolverOptions::runawayFactor),
//   i.e. after its front stopped the segmentation grew by more than any body that front could
//   enclose (a compact structure more than doubled; a thin or branching one, whose front holds
//   far less than the bound, much more). Its site is the box of the voxels that came inside
//   since the slowdown.
// Every quantity is in voxels and iterations: the rule holds for any speed's units (the time
// step makes the fastest front voxel move half a voxel a step) and any structure's size.
class RunawayWatch {
  public:
    static constexpr double kSlowedFraction = 0.2;

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
    bool haveBox_ = false;
    glm::ivec3 boxLo_{0};
    glm::ivec3 boxHi_{0};
};

} // namespace steerseg::solver
