#version 310 es
// Lists the used pool slots: all of them in the band list (settle_bricks keeps the band's
// bookkeeping for sleeping bricks too), the awake ones in the active list (the bricks the step's
// passes process). A sleeping brick's phi does not change, so its last measured front still
// bounds the time step and counts towards the front (slotFront). `wakeAll` (an edit, a
// parameter change) clears every quiet count first. A brick wholly beyond a reach that holds phi
// there (LevelSetSolver::setReach) sleeps whatever its count: no step can change it, so its
// speed (a retrained forest's included) is not evaluated either, and a correction's run costs
// what its reach takes in, not the whole surface. An awake brick whose front cannot have changed
// since measure_speed last measured it (solver/speed_cache.glsl) adds that measure here and is
// left out of the measure list; the others go into it. The last group to finish settles the
// allocation and sizes the passes over the lists (it was prepare_dispatch's one thread).
#include "common/brick_pool.glsl"
#include "solver/solver_common.glsl"
#include "solver/sphere_metric.glsl"
#include "solver/speed_cache.glsl"
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

void listSlot(uint s) {
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
        uint brick = slotBrick[s];
        if (!speedCached(s, brick) || frontMayHaveChanged(s, brickCoord(brick))) {
            activeList[measureListBase() + atomicAdd(ctrl.measureCount, 1u)] = s;
        } else {
            // Its front is as measure_speed last measured it, as a sleeping brick's is: a group
            // of measure_speed (three barriers) for nothing was a third of a small front's step
            // on llvmpipe.
            atomicMax(ctrl.maxRateBits, slotFront[2u * s]);
            atomicAdd(ctrl.frontVoxels, slotFront[2u * s + 1u]);
        }
    }
}

// The allocation's slots leave the free list, its requests are served (an unserved one, after a
// stall, is asked for again by the next settle), and the passes over the lists get their sizes:
// update_phi one group per active brick, measure_speed one per brick to measure, each at least
// one (measure_speed's last group chooses the time step), settle_bricks one per active brick
// and one per 64 band slots.
void prepareDispatch() {
    uint popped = ctrl.popped; // allocate_bricks's, a dispatch before
    ctrl.freeCount -= min(popped, ctrl.freeCount);
    ctrl.popped = 0u;
    ctrl.requestCount = 0u;
    uint awake = atomicAdd(ctrl.activeCount, 0u);
    uint band = atomicAdd(ctrl.bandCount, 0u);
    uvec3 bricks = groupsFor(max(awake, 1u));
    ctrl.brickArgs[0] = bricks.x;
    ctrl.brickArgs[1] = bricks.y;
    ctrl.brickArgs[2] = bricks.z;
    uvec3 measure = groupsFor(max(atomicAdd(ctrl.measureCount, 0u), 1u));
    ctrl.measureArgs[0] = measure.x;
    ctrl.measureArgs[1] = measure.y;
    ctrl.measureArgs[2] = measure.z;
    uvec3 settle = groupsFor(max(awake + (band + 63u) / 64u, 1u));
    ctrl.settleArgs[0] = settle.x;
    ctrl.settleArgs[1] = settle.y;
    ctrl.settleArgs[2] = settle.z;
    ctrl.peakActive = max(ctrl.peakActive, awake);
}

// Every invocation reaches the barrier (GLSL ES 3.10): slots past the capacity only skip work.
void main() {
    uint s = gl_GlobalInvocationID.x;
    if (s < capacity && slotBrick[s] != NO_BRICK) {
        listSlot(s);
    }
    memoryBarrierBuffer(); // this invocation's counts, before its group counts itself done
    barrier();
    if (gl_LocalInvocationIndex == 0u && lastGroupDone()) {
        prepareDispatch();
    }
}
