#version 310 es
// Lists the used pool slots: all of them in the band list (retire and mark keep the band's
// bookkeeping for sleeping bricks too), the awake ones in the active list (the bricks the step's
// passes process). A sleeping brick's phi does not change, so its last measured front still
// bounds the time step and counts towards the front (slotFront). `wakeAll` (an edit, a
// parameter change) clears every quiet count first. A brick wholly beyond a reach that holds phi
// there (LevelSetSolver::setReach) sleeps whatever its count: no step can change it, so its
// speed (a retrained forest's included) is not evaluated either, and a correction's run costs
// what its reach takes in, not the whole surface.
#include "common/brick_pool.glsl"
#include "solver/solver_common.glsl"
#include "solver/sphere_metric.glsl"
layout(local_size_x = 64) in;

uniform uint capacity;
uniform uint sleepAfter; // > 255: never sleep
uniform bool wakeAll;
uniform vec4 heldBeyond; // centre (voxel indices), radius (voxels); radius <= 0: none

// update_phi's test for the brick's voxel nearest the centre (the same for every axis scale: the
// nearest point of a box is clamped axis by axis).
bool beyondReach(uint s) {
    vec3 lo = vec3(brickCoord(slotBrick[s]) * BRICK_SIZE);
    return !inReach(clamp(heldBeyond.xyz, lo, lo + float(BRICK_SIZE - 1)), heldBeyond);
}

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
    if (beyondReach(s)) {
        // Its front is still the surface's; its rate, which no step here takes, bounds none.
        atomicAdd(ctrl.frontVoxels, slotFront[2u * s + 1u]);
    } else if (quietOf(word) >= sleepAfter) {
        atomicMax(ctrl.maxRateBits, slotFront[2u * s]);
        atomicAdd(ctrl.frontVoxels, slotFront[2u * s + 1u]);
    } else {
        activeList[atomicAdd(ctrl.activeCount, 1u)] = s;
    }
}
