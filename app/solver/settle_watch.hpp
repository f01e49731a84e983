#pragma once

#include "solver/front_check.hpp"

#include <cstdint>
#include <deque>

namespace steerseg::solver {

// Tells a front that has settled from one that still moves, from the net volume change: a
// front held at its edges by noise keeps flipping voxels there (so "no voxel changed side for
// N iterations" never holds), but what it gains it loses again, while a front that moves, even
// slowly, adds (or removes) volume steadily. Settled: the net voxels gained over the last
// `window` iterations, spread over the front, are fewer than `tolerance` voxels, i.e. the
// front's mean displacement over the window is below that. Pure (no GL), tested on series.
//
// The defaults (model::SolverOptions::settleIterations, settleDisplacement) are in voxels and
// iterations, never in units of time: the time step is set so that the fastest front voxel moves
// half a voxel a step, whatever the speed's units (HU on CT, dt ~ 1e-3; a unit-contrast phantom, dt
// ~ 0.5), so an iteration is the one clock that means the same motion on every scan. In a window of
// 256 iterations a front moving at that pace would cross 128 voxels: any pause of a moving front
// that is shorter than the window keeps its growth before the pause in the window and is not taken
// for a stop. The tolerance is a twentieth of a voxel over the window (a mean pace of 1/5000 of a
// voxel an iteration, 1/2500 of the fastest front's): a front that keeps that pace moves less than
// a voxel in 5000 more iterations, beyond what a run or an operator's click waits for.
class SettleWatch {
  public:
    // window >= 1 iterations, tolerance in voxels.
    SettleWatch(int window, double tolerance) : window_(window), tolerance_(tolerance) {}
    // Adds a check; true when the front has settled by it.
    bool observe(const FrontCheck& check);
    // After an edit or a parameter change: what follows is a new motion.
    void reset();
    // The front's mean displacement over the window at the last check (voxels; 0 until a
    // window is complete).
    [[nodiscard]] double lastDisplacement() const { return lastDisplacement_; }

  private:
    struct Interval {
        int end = 0; // iteration at its end
        std::int64_t net = 0;
    };
    int window_;
    double tolerance_;
    bool started_ = false;
    int start_ = 0; // the window's first iteration
    std::deque<Interval> checks_;
    std::int64_t windowNet_ = 0;
    double lastDisplacement_ = 0.0;
};

} // namespace steerseg::solver
