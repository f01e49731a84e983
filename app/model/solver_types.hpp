#pragma once

// The solver's options, results and statistics: plain data with no GL type, so the session
// layer and the workflow can hold them without a GPU.
#include <cstddef>
#include <cstdint>
#include <glm/glm.hpp>
#include <optional>

namespace steerseg::model {

// Brick edge in voxels. Measured on llvmpipe (2 cores, bench/solver_bench): see kDefaultBrickSize
// in level_set_solver.cpp for the figures.
int defaultBrickSize();

struct SolverOptions {
    int brickSize = 0;      // 0: defaultBrickSize(); 4, 8 or 16
    bool dense = false;     // every brick active, never retired (benchmark baseline)
    int checkInterval = 16; // iterations between reads of the GPU's counters
    // Invocations per work group of the passes that take one group a brick; 0: the device's
    // (solver::detail::brickGroupSize). The numbers do not depend on it.
    int groupSize = 0;
    // measure_speed finds the front from the sign rows update_phi keeps (solver/front_signs.glsl);
    // false: from the bricks' phi every time, as it does after an edit. The numbers do not
    // depend on it (a test compares the two).
    bool frontFromSignRows = true;
    // Converged: no voxel changed side for convergeIterations iterations spanning at least
    // convergeTime of evolution, or for 10 * convergeIterations iterations (a front held by a
    // strongly negative speed elsewhere takes tiny steps).
    int convergeIterations = 20;
    float convergeTime = 0.5F;
    // Converged too (solver::SettleWatch, which says why these values): the net voxels the
    // front gained over the last settleIterations iterations, spread over the front, are fewer
    // than settleDisplacement voxels. A front held by noise keeps flipping voxels at its edges
    // and never meets the rule above. settleIterations = 0: only the rule above.
    int settleIterations = 256;
    float settleDisplacement = 0.05F;
    // Stop (StopReason::Leak) when the front's growth jumps after a slowdown: the surface broke
    // through a narrow neck into tissue of the same intensity (LeakWatch).
    bool stopOnLeak = false;
    // With stopOnLeak, also a runaway fill (solver::RunawayWatch): after the front's mean speed
    // fell to a fifth of its peak, it gained more than runawayFactor times the volume a ball
    // with that front holds, at no lower a rate than when it slowed. 0: only the jump above.
    // Twice, not once: the front misses the surface a scan's border cuts, so a structure can
    // hold more than the ball (the liver's fill reached 4x it, at a rate that had fallen 16 %
    // by 2x and not at all by 1x: tests/data/growth).
    float runawayFactor = 2.0F;
    // Sleeping bricks (docs/solver.md): a brick none of whose voxels moved by more than
    // sleepTolerance voxels in each of sleepAfter steps in a row is skipped until a neighbour's
    // face, an edit or a parameter change wakes it. Per step, not per unit of time: the step is
    // set so that the fastest front voxel moves half a voxel, whatever the scan's units, while
    // a rate in voxels per unit time would mean 1000x less motion per step on CT (speeds in
    // HU, dt ~ 1e-3) than on a unit-contrast phantom. sleep = false visits every brick of the
    // band every iteration.
    bool sleep = true;
    float sleepTolerance = 1e-3F;
    int sleepAfter = 4; // 1 .. 255
};

// Why a step call returned.
enum class StopReason {
    IterationLimit, // the call's iteration count (step) or maxIterations ran out first
    TimeReached,    // evolveUntil's time was reached (the last step cut to land on it)
    Converged,      // runUntilConverged: converged() holds
    Leak,           // SolverOptions::stopOnLeak: the growth jumped after a slowdown
};
// "iteration_limit", "time_reached", "converged", "leak" (the segment report's stop_reason).
const char* stopReasonName(StopReason reason);

// Which watch saw the leak: the growth jumped after a slowdown (solver::LeakWatch), or the fill
// went on at full rate past what its slowed front could bound (solver::RunawayWatch).
enum class LeakSign {
    GrowthJump,
    RunawayFill,
};
// "growth_jump", "runaway_fill" (the segment report's leak.watch).
const char* leakSignName(LeakSign sign);

// Where the front broke through: the box of the voxels that came inside while the growth
// jumped or ran on (voxel indices, inclusive), the iteration at which the watch was sure, and
// which watch it was.
struct LeakSite {
    glm::ivec3 lo{0};
    glm::ivec3 hi{0};
    int iteration = 0;
    LeakSign sign = LeakSign::GrowthJump;
    [[nodiscard]] glm::vec3 centre() const { return 0.5F * glm::vec3(lo + hi); }
};

struct StepResult {
    int iterations = 0;       // performed by this call
    float evolvedTime = 0.0F; // total since the start
    bool converged = false;   // converged() after the call, whatever stopped it
    StopReason stopReason = StopReason::IterationLimit;
    std::optional<LeakSite> leak; // set when the leak watch stopped the call
};

struct SolverStats {
    int iterations = 0;
    float evolvedTime = 0.0F;
    std::uint32_t activeBricks = 0; // bricks processed (awake) in the last iteration
    std::uint32_t bandBricks = 0;   // bricks stored (asleep or awake) in the last iteration
    std::uint32_t peakActiveBricks = 0;
    std::uint32_t totalBricks = 0;
    std::uint32_t capacity = 0;    // pool slots
    std::size_t levelSetBytes = 0; // phi pool + shell scratch + page table, now
    std::size_t peakLevelSetBytes = 0;
    std::size_t bookkeepingBytes = 0; // slot map, lists, states
    std::size_t speedBytes = 0;       // each slot's speeds, kept between steps
    std::size_t densePhiBytes = 0;    // one float per voxel, for comparison
    int poolGrowths = 0;
    int poolShrinks = 0;
    int stalls = 0; // chunks that ran out of slots before a growth
    // The front's net growth at the last check: voxels that came inside minus those that left,
    // per unit of evolved time (the leak watch's signal).
    float growthRate = 0.0F;
    // Voxels that came inside minus those that left, summed over every check and every sphere
    // edit since the solver was made: the inside count of a run or after an edit follows from
    // one count before it, without reading the mask back (a 512x512x120 mask costs a frame on a
    // software renderer).
    std::int64_t netGained = 0;
    int barriers = 0; // barrier spheres in force
    // Voxels the step's passes visited (the active bricks' voxels), summed over every iteration
    // performed, and its mean per iteration; the front's voxels (a face neighbour on the other
    // side) at the last check. Sleeping bricks keep the first near a small multiple of the last.
    std::uint64_t visitedVoxels = 0;
    double visitedVoxelsPerIteration = 0.0;
    std::uint32_t frontVoxels = 0;
};

} // namespace steerseg::model
