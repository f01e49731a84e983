#version 310 es
// One thread per active brick: a live brick asks for storage for its constant face neighbours,
// which the front may reach next. wantEpoch keeps each brick to one request per pass.
#include "common/brick_pool.glsl"
#include "solver/solver_common.glsl"
layout(local_size_x = 64) in;

layout(std430, binding = REQUESTS_BINDING) writeonly buffer Requests { uint requests[]; };
layout(std430, binding = WANT_EPOCH_BINDING) buffer WantEpoch { uint wantEpoch[]; };

uniform uint epoch;

void main() {
    uint n = gl_GlobalInvocationID.x;
    if (n >= ctrl.activeCount) {
        return;
    }
    uint slot = activeList[n];
    if (slotState[slot] != STATE_LIVE) {
        return;
    }
    ivec3 b = brickCoord(slotBrick[slot]);
    for (int f = 0; f < 6; ++f) {
        ivec3 nb = b + FACE_NEIGHBOURS[f];
        if (!brickInGrid(nb)) {
            continue;
        }
        uint brick = brickIndex(nb);
        if (pageTable[brick] >= BRICK_INSIDE && atomicExchange(wantEpoch[brick], epoch) != epoch) {
            requests[atomicAdd(ctrl.requestCount, 1u)] = brick;
        }
    }
}
