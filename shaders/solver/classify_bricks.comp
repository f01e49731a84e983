#version 310 es
// One group per active brick: its state (live / uniform inside / uniform outside) after an edit
// or an upload, as update_phi.comp records it after a step.
#include "common/brick_pool.glsl"
#include "solver/solver_common.glsl"
#include "solver/brick_state.glsl"
layout(local_size_x = LOCAL_SIZE) in;

void main() {
    uint n = activeListIndex();
    if (n == NO_BRICK) {
        return;
    }
    uint slot = activeList[n];
    ivec3 origin = brickCoord(slotBrick[slot]) * BRICK_SIZE;
    beginBrickState();
    barrier();
    for (uint v = gl_LocalInvocationIndex; v < BRICK_VOXELS; v += uint(LOCAL_SIZE)) {
        if (all(lessThan(origin + localVoxel(v), volumeDims))) {
            noteVoxelState(phiPool[slot * BRICK_VOXELS + v]);
        }
    }
    barrier();
    if (gl_LocalInvocationIndex == 0u) {
        slotState[slot] = brickState();
    }
}
