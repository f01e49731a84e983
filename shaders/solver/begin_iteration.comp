#version 310 es
// One thread: turns the requests of the last mark pass into the allocation's dispatch size and
// clears the per-iteration counters.
#include "common/brick_pool.glsl"
#include "solver/solver_common.glsl"
layout(local_size_x = 1) in;

void main() {
    uint n = ctrl.requestCount;
    ctrl.allocArgs[0] = min(n, GROUPS_PER_ROW);
    ctrl.allocArgs[1] = (n + GROUPS_PER_ROW - 1u) / GROUPS_PER_ROW;
    ctrl.allocArgs[2] = 1u;
    ctrl.popped = 0u;
    ctrl.activeCount = 0u;
    ctrl.maxRateBits = 0u;
    ctrl.bandCount = 0u;
    ctrl.frontVoxels = 0u;
}
