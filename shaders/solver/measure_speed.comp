#version 310 es
// One group per active brick: the largest data speed |alpha * D| on the front, which sets the
// next time step (choose_time_step.comp), and the front's voxels; both kept per slot for the
// iterations the brick sleeps (slotFront).
#include "common/brick_pool.glsl"
#include "solver/solver_common.glsl"
#define DATA_SPEED_INTENSITY_UNIT SOLVER_SCAN_UNIT
#define DATA_SPEED_FACTOR_UNIT SOLVER_FACTOR_UNIT
#include "speed/data_speed.glsl"
#include "solver/barrier_speed.glsl"
#include "solver/phi_stencil.glsl"
#include "solver/phi_tile.glsl"
layout(local_size_x = LOCAL_SIZE) in;

uniform float alpha;
shared uint groupMax;
shared uint groupFront;

// Every invocation reaches both barriers (GLSL ES 3.10): groups past the list only skip work.
void main() {
    uint n = activeListIndex();
    bool hasWork = n != NO_BRICK;
    uint slot = hasWork ? activeList[n] : 0u;
    ivec3 origin = hasWork ? brickCoord(slotBrick[slot]) * BRICK_SIZE : ivec3(0);
    if (hasWork) {
        loadTile(origin);
    }
    if (gl_LocalInvocationIndex == 0u) {
        groupMax = 0u;
        groupFront = 0u;
    }
    barrier();
    float localMax = 0.0;
    uint localFront = 0u;
    for (uint v = gl_LocalInvocationIndex; hasWork && v < BRICK_VOXELS; v += uint(LOCAL_SIZE)) {
        ivec3 l = localVoxel(v);
        ivec3 g = origin + l;
        if (any(greaterThanEqual(g, volumeDims))) {
            continue;
        }
        if (onFront(tileFaces(l))) {
            ++localFront;
            localMax = max(localMax, abs(alpha * barrierSpeed(g, dataSpeed(g))));
        }
    }
    atomicMax(groupMax, floatBitsToUint(localMax));
    atomicAdd(groupFront, localFront);
    barrier();
    if (hasWork && gl_LocalInvocationIndex == 0u) {
        atomicMax(ctrl.maxRateBits, groupMax);
        atomicAdd(ctrl.frontVoxels, groupFront);
        slotFront[2u * slot] = groupMax;
        slotFront[2u * slot + 1u] = groupFront;
    }
}
