#version 310 es
// Compacts the used pool slots into the active list (the bricks the next passes process).
#include "common/brick_pool.glsl"
#include "solver/solver_common.glsl"
layout(local_size_x = 64) in;

uniform uint capacity;

void main() {
    uint s = gl_GlobalInvocationID.x;
    if (s < capacity && slotBrick[s] != NO_BRICK) {
        activeList[atomicAdd(ctrl.activeCount, 1u)] = s;
    }
}
