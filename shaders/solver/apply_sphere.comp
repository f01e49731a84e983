#version 310 es
// One group per brick of a sphere edit's bounding box: phi = min(phi, d) to add the sphere,
// max(phi, -d) to cut it out (d: signed distance to the sphere), clamped. The CPU twin is
// applySphere() in app/solver/phi_init.cpp. The voxels of the scan that change side are added to
// the control block's gained and lost, as a step's are, so that the inside count follows an edit
// without a count of the pool (LevelSetSolver::noteChange folds them into the statistics).
#define PHI_POOL_ACCESS
#include "common/brick_pool.glsl"
#include "solver/solver_common.glsl"
#include "solver/sphere_metric.glsl"
layout(local_size_x = LOCAL_SIZE) in;

uniform ivec3 boxMin;
uniform vec3 centre;
uniform float radius;
uniform bool addMode;

shared uint flipped;

// Every invocation reaches both barriers (GLSL ES 3.10): a brick without a slot only skips work.
void main() {
    ivec3 b = boxMin + ivec3(gl_WorkGroupID);
    uint slot = brickInGrid(b) ? pageTable[brickIndex(b)] : BRICK_INSIDE;
    bool hasWork = slot < BRICK_INSIDE;
    if (gl_LocalInvocationIndex == 0u) {
        flipped = 0u;
    }
    barrier();
    uint localFlipped = 0u;
    for (uint v = gl_LocalInvocationIndex; hasWork && v < BRICK_VOXELS; v += uint(LOCAL_SIZE)) {
        ivec3 g = b * BRICK_SIZE + localVoxel(v);
        float d = sphereDistance(vec3(g) - centre, radius);
        uint at = slot * BRICK_VOXELS + v;
        float before = phiPool[at];
        float p = clamp(addMode ? min(before, d) : max(before, -d), -PHI_FAR, PHI_FAR);
        phiPool[at] = p;
        if ((p < 0.0) != (before < 0.0) && all(lessThan(g, volumeDims))) {
            ++localFlipped;
        }
    }
    if (localFlipped != 0u) {
        atomicAdd(flipped, localFlipped);
    }
    barrier();
    if (gl_LocalInvocationIndex == 0u && flipped != 0u) {
        // An add only brings voxels inside, a cut only takes them out.
        if (addMode) {
            atomicAdd(ctrl.gained, flipped);
        } else {
            atomicAdd(ctrl.lost, flipped);
        }
    }
}
