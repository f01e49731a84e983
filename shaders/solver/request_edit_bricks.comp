#version 310 es
// One thread per brick of a sphere edit's bounding box: constant bricks the edit changes either
// ask for a slot (the surface crosses them) or switch constant at once (fully covered; their
// voxels counted into gained or lost, as apply_sphere.comp counts the rest of the edit).
#define PAGE_TABLE_ACCESS
#include "common/brick_pool.glsl"
#include "solver/solver_common.glsl"
#include "solver/sphere_metric.glsl"
layout(local_size_x = 4, local_size_y = 4, local_size_z = 4) in;

layout(std430, binding = REQUESTS_BINDING) writeonly buffer Requests { uint requests[]; };
layout(std430, binding = WANT_EPOCH_BINDING) buffer WantEpoch { uint wantEpoch[]; };

uniform ivec3 boxMin;  // bricks
uniform ivec3 boxSize; // bricks
uniform vec3 centre;   // voxels
uniform float radius;  // voxels along the finest axis (sphere_metric.glsl)
uniform bool addMode;  // true: union with the sphere, false: cut it out
uniform uint epoch;

void main() {
    ivec3 b = boxMin + ivec3(gl_GlobalInvocationID);
    if (any(greaterThanEqual(ivec3(gl_GlobalInvocationID), boxSize)) || !brickInGrid(b)) {
        return;
    }
    uint brick = brickIndex(b);
    uint old = pageTable[brick];
    // Only the constant on the edit's far side changes: outside under an add, inside under a cut.
    if (old != (addMode ? BRICK_OUTSIDE : BRICK_INSIDE)) {
        return;
    }
    vec3 lo = vec3(b * BRICK_SIZE);
    vec3 hi = vec3(min(b * BRICK_SIZE + BRICK_SIZE, volumeDims) - 1);
    // Bounds on apply_sphere's distance over the brick: it is (norm - radius) / g with g
    // between 1 and the coarsest step, so dividing by the coarsest step is the weaker claim.
    float coarsest = max(sphereScale.x, max(sphereScale.y, sphereScale.z));
    float nearest = (sphereNorm(clamp(centre, lo, hi) - centre) - radius) / coarsest;
    float farthest = (sphereNorm(max(abs(lo - centre), abs(hi - centre))) - radius) / coarsest;
    if (farthest <= -PHI_FAR) {
        pageTable[brick] = addMode ? BRICK_INSIDE : BRICK_OUTSIDE;
        // Its voxels of the scan changed side: counted as apply_sphere counts the others.
        vec3 extent = hi - lo + 1.0;
        uint voxels = uint(extent.x * extent.y * extent.z);
        if (addMode) {
            atomicAdd(ctrl.gained, voxels);
        } else {
            atomicAdd(ctrl.lost, voxels);
        }
    } else if (nearest < PHI_FAR && atomicExchange(wantEpoch[brick], epoch) != epoch) {
        requests[atomicAdd(ctrl.requestCount, 1u)] = brick;
    }
}
