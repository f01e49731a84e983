#version 310 es
// One group per active brick: its state (live / uniform inside / uniform outside) after an edit
// or an upload, as update_phi.comp records it after a step.
#include "common/brick_pool.glsl"
#include "solver/solver_common.glsl"
#include "solver/brick_state.glsl"
layout(local_size_x = LOCAL_SIZE) in;

// Every invocation reaches both barriers (GLSL ES 3.10): groups past the list only skip work.
void main() {
    uint n = activeListIndex();
    bool hasWork = n != NO_BRICK;
    uint slot = hasWork ? activeList[n] : 0u;
    ivec3 origin = hasWork ? brickCoord(slotBrick[slot]) * BRICK_SIZE : ivec3(0);
    beginBrickState();
    barrier();
    uint state = 0u;
    for (uint v = gl_LocalInvocationIndex; hasWork && v < BRICK_VOXELS; v += uint(LOCAL_SIZE)) {
        ivec3 l = localVoxel(v);
        if (all(lessThan(origin + l, volumeDims))) {
            state |= voxelState(l, phiPool[slot * BRICK_VOXELS + v]);
        }
    }
    noteBrickState(state);
    barrier();
    if (hasWork && gl_LocalInvocationIndex == 0u) {
        slotState[slot] = brickState();
    }
}
