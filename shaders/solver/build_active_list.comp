#version 310 es
// Lists the used pool slots: all of them in the band list (retire and mark keep the band's
// bookkeeping for sleeping bricks too), the awake ones in the active list (the bricks the step's
// passes process). A sleeping brick's phi does not change, so its last measured front still
// bounds the time step and counts towards the front (slotFront). `wakeAll` (an edit, a
// parameter change) clears every quiet count first.
#include "common/brick_pool.glsl"
#include "solver/solver_common.glsl"
layout(local_size_x = 64) in;

uniform uint capacity;
uniform uint sleepAfter; // > 255: never sleep
uniform bool wakeAll;

void main() {
    uint s = gl_GlobalInvocationID.x;
    if (s >= capacity || slotBrick[s] == NO_BRICK) {
        return;
    }
    bandList[atomicAdd(ctrl.bandCount, 1u)] = s;
    uint word = slotState[s];
    if (wakeAll) {
        word &= ~QUIET_MASK;
        slotState[s] = word;
    }
    if (quietOf(word) >= sleepAfter) {
        atomicMax(ctrl.maxRateBits, slotFront[2u * s]);
        atomicAdd(ctrl.frontVoxels, slotFront[2u * s + 1u]);
    } else {
        activeList[atomicAdd(ctrl.activeCount, 1u)] = s;
    }
}
