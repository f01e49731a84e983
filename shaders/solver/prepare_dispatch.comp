#version 310 es
// One thread: settles the allocation (slots popped) and sizes the passes over the active list
// (awake bricks) and the band list (every used slot).
#include "common/brick_pool.glsl"
#include "solver/solver_common.glsl"
layout(local_size_x = 1) in;

void main() {
    ctrl.freeCount -= min(ctrl.popped, ctrl.freeCount);
    ctrl.popped = 0u;
    ctrl.requestCount = 0u;
    uint n = ctrl.activeCount;
    ctrl.brickArgs[0] = min(n, GROUPS_PER_ROW);
    ctrl.brickArgs[1] = (n + GROUPS_PER_ROW - 1u) / GROUPS_PER_ROW;
    ctrl.brickArgs[2] = 1u;
    ctrl.listArgs[0] = (ctrl.bandCount + 63u) / 64u;
    ctrl.listArgs[1] = 1u;
    ctrl.listArgs[2] = 1u;
    ctrl.peakActive = max(ctrl.peakActive, n);
}
