#version 310 es
// One thread per used slot. A brick whose step moved a face by more than the sleep tolerance
// wakes the neighbours whose stencils read that face (across the face, and across an edge of
// two moved faces: the stencil has face and edge neighbours, no corners). A live brick asks for storage for a constant face neighbour
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
    if (n >= ctrl.bandCount) {
        return;
    }
    uint slot = bandList[n];
    uint word = slotState[slot];
    ivec3 b = brickCoord(slotBrick[slot]);
    uint moved = word >> MOVED_SHIFT;
    for (int d = 0; moved != 0u && d < 27; ++d) {
        ivec3 o = ivec3(d % 3, (d / 3) % 3, d / 9) - 1;
        int axes = abs(o.x) + abs(o.y) + abs(o.z);
        uvec3 faceBit = uvec3(1u, 4u, 16u) << uvec3(greaterThan(o, ivec3(0)));
        uvec3 need = uvec3(notEqual(o, ivec3(0))) * faceBit;
        uint needed = need.x | need.y | need.z;
        ivec3 nb = b + o;
        if (axes == 0 || axes == 3 || (moved & needed) != needed || !brickInGrid(nb)) {
            continue;
        }
        uint s = pageTable[brickIndex(nb)];
        if (s < BRICK_INSIDE) {
            atomicAnd(slotState[s], ~QUIET_MASK);
        }
    }
    if (stateOf(word) != STATE_LIVE) {
        return;
    }
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
