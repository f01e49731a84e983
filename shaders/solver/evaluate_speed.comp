#version 310 es
// The classifier speed evaluated where the front goes (docs/speed.md, "Evaluation", "Where
// the front goes"): one group per brick, which stores speed/classifier_forest.glsl's value at each
// of its voxels into the solver's factor texture the first time the brick is asked for, and marks
// it ready. The solver runs it over the active list before the passes that read the data speed
// (measure_speed, update_phi read it only at their own brick's voxels), so a brick's speed is
// there before its first read; the host's fill-in (LevelSetSolver::evaluateSpeedAhead) runs it
// over a range of bricks, for a speed view of the whole scan.
precision highp float;
precision highp int;
precision highp sampler3D;
precision highp image3D;
#include "common/brick_pool.glsl"
#include "solver/solver_common.glsl"
#include "speed/classifier_forest.glsl"
layout(local_size_x = LOCAL_SIZE) in;

// [0] bricks evaluated since the last reset; [1 + brick] non-zero once brick's speed is stored.
layout(std430, binding = SPEED_READY_BINDING) buffer SpeedReady {
    uint speedReady[];
};
layout(r32f, binding = SOLVER_SPEED_IMAGE_UNIT) uniform writeonly image3D speedOut;
uniform int fromActiveList; // 1: the active list's bricks; 0: bricks firstBrick + group
uniform uint firstBrick;

shared bool alreadyReady;

// Every invocation reads the ready word before any marks it: llvmpipe runs a group's invocations
// in turns, so a later turn would see the mark its own group's first turn had just left.
void main() {
    uint brick = NO_BRICK;
    if (fromActiveList != 0) {
        uint n = activeListIndex();
        brick = n != NO_BRICK ? slotBrick[activeList[n]] : NO_BRICK;
    } else if (int(firstBrick + gl_WorkGroupID.x) < brickGrid.x * brickGrid.y * brickGrid.z) {
        brick = firstBrick + gl_WorkGroupID.x;
    }
    if (gl_LocalInvocationIndex == 0u) {
        alreadyReady = brick == NO_BRICK || speedReady[1u + brick] != 0u;
    }
    barrier();
    if (alreadyReady) {
        return;
    }
    ivec3 origin = brickCoord(brick) * BRICK_SIZE;
    for (uint v = gl_LocalInvocationIndex; v < BRICK_VOXELS; v += uint(LOCAL_SIZE)) {
        ivec3 g = origin + localVoxel(v);
        if (all(lessThan(g, volumeDims))) {
            imageStore(speedOut, g, vec4(classifierSpeedAt(g), 0.0, 0.0, 0.0));
        }
    }
    if (gl_LocalInvocationIndex == 0u) {
        // Each brick is in the active list at most once, so no other group writes this word.
        speedReady[1u + brick] = 1u;
        atomicAdd(speedReady[0], 1u);
    }
}
