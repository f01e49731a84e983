#version 310 es
// One group per requested brick: pops a free slot, fills it with the brick's constant value
// (in the current phi buffer) and its sign rows (solver/speed_cache.glsl), and points the page
// table at it. Without a free slot the request stays unserved and `stalled` pauses the
// iterations until the host grows the pool.
// With EVALUATE_SPEED (the classify speed evaluated where the front goes, solver/speed_on_demand)
// it also stores the classifier's speed at the new brick's voxels, as evaluate_speed.comp does
// for the active list, unless the brick holds it already: a brick the band reaches next
// iteration gets its speed here rather than in a dispatch of its own every iteration. The
// passes that read it (measure_speed) run behind the memory barrier after this one.
precision highp float;
precision highp int;
#define PAGE_TABLE_ACCESS
#define PHI_POOL_ACCESS
#include "common/brick_pool.glsl"
#include "solver/solver_common.glsl"
#include "solver/speed_cache.glsl"
#ifdef EVALUATE_SPEED
precision highp sampler3D;
precision highp image3D;
#include "speed/classifier_forest.glsl"
// [0] bricks evaluated since the last reset; [1 + brick] non-zero once brick's speed is stored.
layout(std430, binding = SPEED_READY_BINDING) buffer SpeedReady { uint speedReady[]; };
layout(r32f, binding = SOLVER_SPEED_IMAGE_UNIT) uniform writeonly image3D speedOut;
#endif
layout(local_size_x = LOCAL_SIZE) in;

layout(std430, binding = FREE_LIST_BINDING) readonly buffer FreeList { uint freeList[]; };
layout(std430, binding = REQUESTS_BINDING) readonly buffer Requests { uint requests[]; };

shared uint slot;
shared bool evaluate;

// Every invocation reaches the barrier (GLSL ES 3.10): groups past the requests only skip work.
void main() {
    uint request = gl_WorkGroupID.x + gl_WorkGroupID.y * GROUPS_PER_ROW;
    bool hasWork = request < ctrl.requestCount;
    uint brick = hasWork ? requests[request] : 0u;
    uint old = hasWork ? pageTable[brick] : BRICK_OUTSIDE;
    if (gl_LocalInvocationIndex == 0u) {
        slot = NO_BRICK;
        evaluate = false;
        if (hasWork) {
            uint k = atomicAdd(ctrl.popped, 1u);
            if (k < ctrl.freeCount) {
                slot = freeList[ctrl.freeCount - 1u - k];
            } else {
                ctrl.stalled = 1u;
            }
        }
#ifdef EVALUATE_SPEED
        // Read by this invocation alone, before it marks the brick below: requests are
        // deduplicated, so no other group allocates this brick.
        evaluate = slot != NO_BRICK && speedReady[1u + brick] == 0u;
#endif
    }
    barrier();
    bool fill = hasWork && slot != NO_BRICK;
    float value = old == BRICK_INSIDE ? -PHI_FAR : PHI_FAR;
    for (uint v = gl_LocalInvocationIndex; fill && v < BRICK_VOXELS; v += uint(LOCAL_SIZE)) {
        phiPool[slot * BRICK_VOXELS + v] = value;
    }
    for (uint r = gl_LocalInvocationIndex; fill && r < SIGN_ROWS; r += uint(LOCAL_SIZE)) {
        storeSignRow(slot, r, value < 0.0 ? ROW_BITS : 0u);
    }
#ifdef EVALUATE_SPEED
    ivec3 origin = brickCoord(brick) * BRICK_SIZE;
    for (uint v = gl_LocalInvocationIndex; evaluate && v < BRICK_VOXELS; v += uint(LOCAL_SIZE)) {
        ivec3 g = origin + localVoxel(v);
        if (all(lessThan(g, volumeDims))) {
            imageStore(speedOut, g, vec4(classifierSpeedAt(g), 0.0, 0.0, 0.0));
        }
    }
    if (evaluate && gl_LocalInvocationIndex == 0u) {
        speedReady[1u + brick] = 1u;
        atomicAdd(speedReady[0], 1u);
    }
#endif
    if (fill && gl_LocalInvocationIndex == 0u) {
        slotBrick[slot] = brick;
        slotState[slot] = old == BRICK_INSIDE ? STATE_INSIDE : STATE_OUTSIDE;
        pageTable[brick] = slot;
        forgetMeasured(slot); // what measure_speed kept is another brick's
        noteSignsKept(slot, true);
    }
}
