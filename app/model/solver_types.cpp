#include "model/solver_types.hpp"

namespace steerseg::model {

namespace {

// Brick edge, measured with solver_bench on llvmpipe (2 cores, idle, 96^3, sphere r = 24):
// 4 -> 14.9 it/s (143k active voxels), 8 -> 19.1 it/s (254k), 16 -> 11.0 it/s (569k). 8 is the
// fastest per iteration with 1.8x 4's voxels, and its apron tile (4 KB) fits the 16 KB
// shared-memory minimum of GLES 3.1, which 16 (23 KB) does not.
constexpr int kDefaultBrickSize = 8;

} // namespace

int defaultBrickSize() {
    return kDefaultBrickSize;
}

const char* stopReasonName(StopReason reason) {
    switch (reason) {
    case StopReason::IterationLimit:
        return "iteration_limit";
    case StopReason::TimeReached:
        return "time_reached";
    case StopReason::Converged:
        return "converged";
    case StopReason::Leak:
        return "leak";
    }
    return "unknown";
}

const char* leakSignName(LeakSign sign) {
    switch (sign) {
    case LeakSign::GrowthJump:
        return "growth_jump";
    case LeakSign::RunawayFill:
        return "runaway_fill";
    }
    return "unknown";
}

} // namespace steerseg::model
