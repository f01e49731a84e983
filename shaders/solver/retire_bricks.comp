#version 310 es
// One thread per used slot (asleep or awake): a brick that became uniform (all -PHI_FAR or all +PHI_FAR) and
// that no face neighbour's band reaches (the rule mark_wanted_bricks requests storage by) gives
// its slot back and becomes BRICK_INSIDE / BRICK_OUTSIDE.
#define PAGE_TABLE_ACCESS
#include "common/brick_pool.glsl"
#include "solver/solver_common.glsl"
layout(local_size_x = 64) in;

layout(std430, binding = FREE_LIST_BINDING) buffer FreeList { uint freeList[]; };

void main() {
    uint n = gl_GlobalInvocationID.x;
    if (n >= ctrl.bandCount) {
        return;
    }
    uint slot = bandList[n];
    uint state = stateOf(slotState[slot]);
    if (state == STATE_LIVE || state == STATE_MIXED) {
        return;
    }
    uint brick = slotBrick[slot];
    ivec3 b = brickCoord(brick);
    for (int f = 0; f < 6; ++f) {
        ivec3 nb = b + FACE_NEIGHBOURS[f];
        if (brickInGrid(nb)) {
            uint s = pageTable[brickIndex(nb)];
            // FACE_NEIGHBOURS pairs opposite faces: f ^ 1 is the neighbour's face towards us.
            if (s < BRICK_INSIDE && reachesFace(slotState[s], f ^ 1)) {
                return;
            }
        }
    }
    pageTable[brick] = state == STATE_INSIDE ? BRICK_INSIDE : BRICK_OUTSIDE;
    slotBrick[slot] = NO_BRICK;
    freeList[atomicAdd(ctrl.freeCount, 1u)] = slot;
}
