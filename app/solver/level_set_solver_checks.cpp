// The run between the solver's checks: a chunk of iterations without host sync, then one
// readback that feeds the statistics, the leak, settle and runaway watches, and the pool's size.
// Kept apart from level_set_solver.cpp so that the passes and the checks each read on their own.
#include "gpu/gl_error.hpp"
#include "gpu/gl_state_guard.hpp"
#include "solver/gpu_brick_pool.hpp"
#include "solver/level_set_solver.hpp"

#include <algorithm>
#include <cstdint>
#include <optional>

namespace steerseg::solver {

using detail::ControlBlock;

model::StepResult LevelSetSolver::advance(int maxIterations, float timeLimit, bool untilConverged) {
    requireParams();
    gpu::GlStateGuard guard;
    pool_->bind();
    bindSpeed();
    // The block as the last call left it: no GPU sync before the first chunk, so a caller that
    // steps a few iterations per frame pays one readback per call (after its chunk).
    ControlBlock ctrl = known_ ? *known_ : pool_->readControl();
    known_.reset(); // unknown if this call throws
    if (!options_.dense && ctrl.requestCount > ctrl.freeCount &&
        pool_->capacity() < pool_->maxCapacity()) {
        // The requests an edit or the last call left (a new seed's neighbours) would stall the
        // first chunk, which then runs for nothing: make room for them now.
        const std::uint32_t used = pool_->usedSlots(ctrl);
        pool_->grow(detail::poolTarget(used, 0, ctrl.requestCount), ctrl);
        ++stats_.poolGrowths;
        pool_->bind();
        ctrl = pool_->readControl();
    }
    const std::uint32_t start = ctrl.iteration;
    if (!checkOrigin_) {
        checkOrigin_ = start;
    }
    const auto interval = static_cast<std::uint32_t>(options_.checkInterval);
    int remaining = maxIterations;
    std::optional<model::LeakSite> leak;
    while (remaining > 0) {
        // Up to the run's next check. A call that ends before it (a frame's share) reads the
        // block for its figures but leaves the growth counters to the check, whose interval
        // the watches then see whole: when a check falls cannot depend on the frame rate.
        const auto toCheck =
            static_cast<int>(interval - (ctrl.iteration - *checkOrigin_) % interval);
        const int chunk = std::min(remaining, toCheck);
        for (int n = 0; n < chunk; ++n) {
            iterate(timeLimit);
        }
        const std::uint32_t before = ctrl.iteration;
        ctrl = pool_->readControl();
        const int done = static_cast<int>(ctrl.iteration - before);
        remaining -= done;
        const auto sinceChange = static_cast<int>(ctrl.iteration - ctrl.lastChange);
        // With every brick asleep nothing can change any more: converged at once.
        converged_ = (sinceChange >= options_.convergeIterations &&
                      (ctrl.time - ctrl.lastChangeTime >= options_.convergeTime ||
                       sinceChange >= 10 * options_.convergeIterations)) ||
                     (ctrl.shownActive == 0 && ctrl.shownBand > 0 && done > 0);
        stats_.peakActiveBricks = std::max(stats_.peakActiveBricks, ctrl.peakActive);
        if (ctrl.stalled != 0) {
            ++stats_.stalls;
            if (pool_->capacity() >= pool_->maxCapacity()) {
                throw gpu::GpuCapacityError("the level set outgrew " + pool_->capacityLimitText());
            }
            // The band outran the margin: grow for twice the advance it made by now.
            const std::uint32_t used = pool_->usedSlots(ctrl);
            const std::uint32_t growth = used > lastUsed_ ? used - lastUsed_ : used / 4;
            pool_->grow(detail::poolTarget(used, 2 * growth, ctrl.requestCount), ctrl);
            ++stats_.poolGrowths;
            pool_->bind();
            ctrl = pool_->readControl();
            continue;
        }
        takeVisits(ctrl);
        if ((ctrl.iteration - *checkOrigin_) % interval == 0) {
            leak = watchGrowth(ctrl);
        } else {
            pool_->writeControl(ctrl); // the visits taken, the growth left to the check
        }
        converged_ = converged_ || settled_;
        if ((untilConverged && converged_) || done < chunk || leak) {
            break; // converged, the time limit stopped the steps, or a leak
        }
        if (managePool(ctrl)) {
            ctrl = pool_->readControl();
        }
    }
    stats_.peakLevelSetBytes = std::max(stats_.peakLevelSetBytes, pool_->levelSetBytes());
    lastIteration_ = static_cast<int>(ctrl.iteration);
    lastTime_ = ctrl.time;
    stats_.activeBricks = ctrl.shownActive;
    stats_.bandBricks = ctrl.shownBand;
    stats_.frontVoxels = ctrl.shownFront;
    known_ = ctrl;
    model::StopReason reason = model::StopReason::IterationLimit;
    if (leak) {
        reason = model::StopReason::Leak;
    } else if (untilConverged && converged_) {
        reason = model::StopReason::Converged;
    } else if (ctrl.time >= timeLimit) {
        reason = model::StopReason::TimeReached;
    }
    return {static_cast<int>(ctrl.iteration - start), ctrl.time, converged_, reason, leak};
}

// Moves the GPU's count of visited bricks into the statistics; watchGrowth writes the cleared
// block back with its own counters.
void LevelSetSolver::takeVisits(ControlBlock& ctrl) {
    const auto b = static_cast<std::uint64_t>(options_.brickSize);
    stats_.visitedVoxels += static_cast<std::uint64_t>(ctrl.visitedBricks) * b * b * b;
    ctrl.visitedBricks = 0;
}

// The leak watch's check: this interval's growth from update_phi's counters, which are then
// cleared on the GPU (`ctrl` is fresh and the GPU idle). A leak only when stopOnLeak asks.
std::optional<model::LeakSite> LevelSetSolver::watchGrowth(ControlBlock& ctrl) {
    GrowthSample sample;
    sample.time = ctrl.time;
    sample.iteration = static_cast<int>(ctrl.iteration);
    sample.net = static_cast<std::int64_t>(ctrl.gained) - static_cast<std::int64_t>(ctrl.lost);
    sample.anyGained = ctrl.gained > 0;
    if (sample.anyGained) {
        sample.gainLo =
            glm::ivec3(static_cast<int>(ctrl.gainLo[0]), static_cast<int>(ctrl.gainLo[1]),
                       static_cast<int>(ctrl.gainLo[2]));
        sample.gainHi =
            glm::ivec3(static_cast<int>(ctrl.gainHi[0]), static_cast<int>(ctrl.gainHi[1]),
                       static_cast<int>(ctrl.gainHi[2]));
    }
    stats_.netGained += sample.net;
    const FrontCheck check{sample.iteration, sample.time,   ctrl.gained,  ctrl.lost,
                           ctrl.shownFront,  sample.gainLo, sample.gainHi};
    if (checkObserver_) {
        checkObserver_(check);
    }
    detail::clearGrowth(ctrl);
    pool_->writeControl(ctrl);
    settled_ = options_.settleIterations > 0 && settleWatch_.observe(check);
    std::optional<model::LeakSite> leak = leakWatch_.observe(sample);
    std::optional<model::LeakSite> runaway =
        options_.runawayFactor > 0.0F ? runawayWatch_.observe(check) : std::nullopt;
    stats_.growthRate = static_cast<float>(leakWatch_.lastRate());
    if (!options_.stopOnLeak) {
        return std::nullopt;
    }
    return leak ? leak : runaway;
}

// Keeps a margin of free slots for the band's advance until the next check, and gives memory
// back when the surface shrank, so that storage follows the band (poolTarget). A run that still
// outpaces the margin stalls and is grown above. `ctrl` is fresh; returns whether the pool
// changed (and with it the control block).
bool LevelSetSolver::managePool(const ControlBlock& ctrl) {
    if (options_.dense) {
        return false;
    }
    const std::uint32_t used = pool_->usedSlots(ctrl);
    const std::uint32_t growth = used > lastUsed_ ? used - lastUsed_ : 0;
    lastUsed_ = used;
    const std::uint32_t target = detail::poolTarget(used, growth, ctrl.requestCount);
    if (ctrl.freeCount < used / 32 + growth + ctrl.requestCount + 2 &&
        pool_->capacity() < pool_->maxCapacity()) {
        pool_->grow(target, ctrl);
        ++stats_.poolGrowths;
    } else if (pool_->capacity() > target + used / 16 + 4) {
        pool_->shrink(target, ctrl);
        ++stats_.poolShrinks;
    } else {
        return false;
    }
    stats_.peakLevelSetBytes = std::max(stats_.peakLevelSetBytes, pool_->levelSetBytes());
    pool_->bind();
    return true;
}

} // namespace steerseg::solver
