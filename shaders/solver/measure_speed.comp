#version 310 es
// One group per active brick build_active_list put in the measure list (its front may have
// changed since it was last measured, or its slot has no speeds: solver/speed_cache.glsl): the
// largest data speed |alpha * D| on the front, which sets the next time step, and the front's
// voxels; both kept per slot for the iterations the brick sleeps or its front stays (slotFront).
// The first pass of an iteration over the bricks, so it fills the speeds of a brick whose slot
// has none. The last group to finish chooses the time step from every group's maximum and those
// the list added (it was choose_time_step's one thread).
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
uniform float courant;
uniform float fixedRate;
uniform float timeLimit;
shared uint groupMax;
shared uint groupFront;
shared bool fillSpeed;
shared bool measureFront;

// dt = 1 / (max |alpha * D| / courant + fixedRate), fixedRate = the rescaling term's speed /
// courant + the curvature term's diffusion rate (the bound it obeys: TimeStepRule in
// app/model/level_set_params.hpp), cut to reach timeLimit exactly; no step while stalled.
void chooseTimeStep() {
    float maxRate = uintBitsToFloat(atomicOr(ctrl.maxRateBits, 0u));
    float dt = 1.0 / (maxRate / courant + fixedRate);
    dt = min(dt, timeLimit - ctrl.time);
    if (ctrl.stalled != 0u || !(dt > 0.0)) {
        dt = 0.0;
    }
    ctrl.dt = dt;
    if (dt > 0.0) {
        ctrl.time += dt;
        ctrl.iteration += 1u;
        ctrl.visitedBricks += ctrl.activeCount;
    }
}

// Every invocation reaches every barrier (GLSL ES 3.10): groups past the list only skip work.
void main() {
    uint n = gl_WorkGroupID.x + gl_WorkGroupID.y * GROUPS_PER_ROW;
    bool hasWork = n < ctrl.measureCount;
    uint slot = hasWork ? activeList[measureListBase() + n] : 0u;
    uint brick = hasWork ? slotBrick[slot] : 0u;
    ivec3 origin = brickCoord(brick) * BRICK_SIZE;
    if (gl_LocalInvocationIndex == 0u) {
        groupMax = 0u;
        groupFront = 0u;
        fillSpeed = hasWork && !speedCached(slot, brick);
        measureFront = hasWork;
    }
    barrier();
    if (measureFront) {
        loadTile(origin, slot);
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
    // Only this invocation updates the counters the time step reads: no barrier() needed.
    if (gl_LocalInvocationIndex == 0u && lastGroupDone()) {
        chooseTimeStep();
    }
}
