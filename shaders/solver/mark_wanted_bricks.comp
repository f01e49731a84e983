#version 310 es
// One thread per active brick: a live brick asks for storage for a constant face neighbour
// when the band reaches the face they share (a voxel on it has |phi| < PHI_FAR, so the voxels
// across it step next iteration; solver_common.glsl's FACE_REACH_SHIFT). The first version
// asked for all six neighbours of every live brick, most of which the band never entered.
// wantEpoch keeps each brick to one request per pass.
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
    uint word = slotState[slot];
    if (stateOf(word) != STATE_LIVE) {
        return;
    }
    ivec3 b = brickCoord(slotBrick[slot]);
    for (int f = 0; f < 6; ++f) {
        ivec3 nb = b + FACE_NEIGHBOURS[f];
        if (!reachesFace(word, f) || !brickInGrid(nb)) {
            continue;
        }
        uint brick = brickIndex(nb);
        if (pageTable[brick] >= BRICK_INSIDE && atomicExchange(wantEpoch[brick], epoch) != epoch) {
            requests[atomicAdd(ctrl.requestCount, 1u)] = brick;
        }
    }
}
