#version 310 es
// One group per active brick build_active_list put in the measure list (its front may have
// changed since it was last measured, or its slot has no speeds: solver/speed_cache.glsl): the
// largest data speed |alpha * D| on the front, which sets the next time step, and the front's
// voxels; both kept per slot for the iterations the brick sleeps or its front stays (slotFront).
// The first pass of an iteration over the bricks, so it fills the speeds of a brick whose slot
// has none. It finds the front from the sign rows the brick and its face neighbours keep
// (solver/front_signs.glsl), or, where one of them keeps none (after an edit or a shrink), from
// the brick's phi and its apron. The last group to finish chooses the time step from every
// group's maximum and those the list added (it was choose_time_step's one thread).
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
#include "solver/front_signs.glsl"
layout(local_size_x = LOCAL_SIZE) in;

uniform float alpha;
uniform float courant;
uniform float fixedRate;
uniform float timeLimit;
uniform bool signRows; // false: always from phi (SolverOptions::frontFromSignRows)
shared uint groupMax;
shared uint groupFront;
shared bool fillSpeed;
shared bool measureFront;
shared bool fromSigns;

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

// The rate a front voxel's speed sets the time step by. Under classify the data term lies in
// [-1, 1], and a barrier's hold (barrier_speed.glsl, at least 1 / alpha) would otherwise set the
// time step wherever the front touches a barrier or the box's faces, which under classify is most
// of a run: up to 1.7x as many steps for the same evolved time. The hold needs no share of the
// step: alpha * hold is the rescaling and curvature terms' fixedRate / 2 (uploadBarriers), so it
// moves a voxel at most courant voxels a step on its own, and it only fixes the side.
float timeStepRate(float speed) {
    return alpha * (speedKind == 2 ? min(abs(speed), 1.0) : abs(speed));
}

// Voxel v of the slot, at grid voxel g: its speed stored where the slot keeps none, and, on the
// front, counted with the rate it sets the time step by.
void measureVoxel(uint slot, uint v, ivec3 g, bool front, inout uint count, inout float rate) {
    float speed = fillSpeed ? storeSpeed(slot, v, barrierSpeed(g, dataSpeed(g))) : 0.0;
    if (front) {
        ++count;
        rate = max(rate, timeStepRate(fillSpeed ? speed : cachedSpeed(slot, v)));
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
        fromSigns = hasWork && signRows && findFaceSlots(slot, brickCoord(brick));
    }
    barrier();
    if (measureFront && !fromSigns) {
        loadTile(origin, slot);
    }
    barrier();
    float localMax = 0.0;
    uint localFront = 0u;
    const int ROWS = BRICK_SIZE * BRICK_SIZE;
    for (int row = int(gl_LocalInvocationIndex); fromSigns && row < ROWS; row += LOCAL_SIZE) {
        int y = row % BRICK_SIZE;
        int z = row / BRICK_SIZE;
        ivec3 g = origin + ivec3(0, y, z);
        if (g.y >= volumeDims.y || g.z >= volumeDims.z) {
            continue;
        }
        uint front = frontRow(slot, origin, y, z);
        uint v0 = uint(BRICK_SIZE * row);
        if (fillSpeed) { // every voxel of the row
            int width = min(BRICK_SIZE, volumeDims.x - origin.x);
            for (int x = 0; x < width; ++x) {
                bool onIt = ((front >> uint(x)) & 1u) != 0u;
                measureVoxel(slot, v0 + uint(x), g + ivec3(x, 0, 0), onIt, localFront, localMax);
            }
        } else { // the front's voxels only
            for (uint bits = front; bits != 0u; bits &= bits - 1u) {
                int x = findLSB(bits);
                measureVoxel(slot, v0 + uint(x), g + ivec3(x, 0, 0), true, localFront, localMax);
            }
        }
    }
    for (uint v = gl_LocalInvocationIndex; measureFront && !fromSigns && v < BRICK_VOXELS;
         v += uint(LOCAL_SIZE)) {
        ivec3 l = localVoxel(v);
        ivec3 g = origin + l;
        if (any(greaterThanEqual(g, volumeDims))) {
            continue;
        }
        measureVoxel(slot, v, g, onFront(tileFaces(l)), localFront, localMax);
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
