#version 310 es
// One group per active brick: the largest data speed |alpha * D| on the front, which sets the
// next time step (choose_time_step.comp), and the front's voxels; both kept per slot for the
// iterations the brick sleeps (slotFront). The first pass of an iteration over the active
// bricks, so it fills the speeds of a brick whose slot has none, and it measures only a brick
// whose front may have changed since it last did (solver/speed_cache.glsl).
#include "common/brick_pool.glsl"
#include "solver/solver_common.glsl"
#define DATA_SPEED_INTENSITY_UNIT SOLVER_SCAN_UNIT
#define DATA_SPEED_FACTOR_UNIT SOLVER_FACTOR_UNIT
#include "speed/data_speed.glsl"
#include "solver/sphere_metric.glsl"
#include "solver/barrier_speed.glsl"
#include "solver/phi_stencil.glsl"
#include "solver/phi_tile.glsl"
#include "solver/speed_cache.glsl"
layout(local_size_x = LOCAL_SIZE) in;

uniform float alpha;
shared uint groupMax;
shared uint groupFront;
shared bool fillSpeed;
shared bool measureFront;

// Every invocation reaches every barrier (GLSL ES 3.10): groups past the list only skip work.
void main() {
    uint n = activeListIndex();
    bool hasWork = n != NO_BRICK;
    uint slot = hasWork ? activeList[n] : 0u;
    uint brick = hasWork ? slotBrick[slot] : 0u;
    ivec3 origin = brickCoord(brick) * BRICK_SIZE;
    if (gl_LocalInvocationIndex == 0u) {
        groupMax = 0u;
        groupFront = 0u;
        fillSpeed = hasWork && !speedCached(slot, brick);
        measureFront = hasWork && (fillSpeed || frontMayHaveChanged(slot, brickCoord(brick)));
    }
    barrier();
    if (measureFront) {
        loadTile(origin);
    }
    barrier();
    float localMax = 0.0;
    uint localFront = 0u;
    for (uint v = gl_LocalInvocationIndex; measureFront && v < BRICK_VOXELS;
         v += uint(LOCAL_SIZE)) {
        ivec3 l = localVoxel(v);
        ivec3 g = origin + l;
        if (any(greaterThanEqual(g, volumeDims))) {
            continue;
        }
        float speed = fillSpeed ? storeSpeed(slot, v, barrierSpeed(g, dataSpeed(g))) : 0.0;
        if (onFront(tileFaces(l))) {
            ++localFront;
            localMax = max(localMax, abs(alpha * (fillSpeed ? speed : cachedSpeed(slot, v))));
        }
    }
    atomicMax(groupMax, floatBitsToUint(localMax));
    atomicAdd(groupFront, localFront);
    barrier();
    // After the barrier: every invocation has read fillSpeed and measureFront.
    if (hasWork && gl_LocalInvocationIndex == 0u) {
        if (measureFront) {
            slotFront[2u * slot] = groupMax;
            slotFront[2u * slot + 1u] = groupFront;
            noteMeasured(slot, ctrl.iteration);
            if (fillSpeed) {
                markSpeedCached(slot, brick);
            }
        }
        atomicMax(ctrl.maxRateBits, slotFront[2u * slot]);
        atomicAdd(ctrl.frontVoxels, slotFront[2u * slot + 1u]);
    }
}
