#version 310 es
// One group per requested brick: pops a free slot, fills it with the brick's constant value
// (in the current phi buffer) and points the page table at it. Without a free slot the request
// stays unserved and `stalled` pauses the iterations until the host grows the pool.
#define PAGE_TABLE_ACCESS
#define PHI_POOL_ACCESS
#include "common/brick_pool.glsl"
#include "solver/solver_common.glsl"
#include "solver/speed_cache.glsl"
layout(local_size_x = LOCAL_SIZE) in;

layout(std430, binding = FREE_LIST_BINDING) readonly buffer FreeList { uint freeList[]; };
layout(std430, binding = REQUESTS_BINDING) readonly buffer Requests { uint requests[]; };

shared uint slot;

// Every invocation reaches the barrier (GLSL ES 3.10): groups past the requests only skip work.
void main() {
    uint request = gl_WorkGroupID.x + gl_WorkGroupID.y * GROUPS_PER_ROW;
    bool hasWork = request < ctrl.requestCount;
    uint brick = hasWork ? requests[request] : 0u;
    uint old = hasWork ? pageTable[brick] : BRICK_OUTSIDE;
    if (hasWork && gl_LocalInvocationIndex == 0u) {
        uint k = atomicAdd(ctrl.popped, 1u);
        if (k < ctrl.freeCount) {
            slot = freeList[ctrl.freeCount - 1u - k];
        } else {
            slot = NO_BRICK;
            ctrl.stalled = 1u;
        }
    }
    barrier();
    if (!hasWork || slot == NO_BRICK) {
        return;
    }
    float value = old == BRICK_INSIDE ? -PHI_FAR : PHI_FAR;
    for (uint v = gl_LocalInvocationIndex; v < BRICK_VOXELS; v += uint(LOCAL_SIZE)) {
        phiPool[slot * BRICK_VOXELS + v] = value;
    }
    if (gl_LocalInvocationIndex == 0u) {
        slotBrick[slot] = brick;
        slotState[slot] = old == BRICK_INSIDE ? STATE_INSIDE : STATE_OUTSIDE;
        pageTable[brick] = slot;
        forgetMeasured(slot); // what measure_speed kept is another brick's
    }
}
