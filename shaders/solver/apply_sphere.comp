#version 310 es
// One group per brick of a sphere edit's bounding box: phi = min(phi, d) to add the sphere,
// max(phi, -d) to cut it out (d: signed distance to the sphere), clamped. The CPU twin is
// applySphere() in app/solver/phi_init.cpp.
#define PHI_POOL_ACCESS
#include "common/brick_pool.glsl"
#include "solver/solver_common.glsl"
layout(local_size_x = LOCAL_SIZE) in;

uniform ivec3 boxMin;
uniform vec3 centre;
uniform float radius;
uniform bool addMode;

void main() {
    ivec3 b = boxMin + ivec3(gl_WorkGroupID);
    if (!brickInGrid(b)) {
        return;
    }
    uint slot = pageTable[brickIndex(b)];
    if (slot >= BRICK_INSIDE) {
        return;
    }
    for (uint v = gl_LocalInvocationIndex; v < BRICK_VOXELS; v += uint(LOCAL_SIZE)) {
        vec3 g = vec3(b * BRICK_SIZE + localVoxel(v));
        float d = length(g - centre) - radius;
        uint at = slot * BRICK_VOXELS + v;
        float p = addMode ? min(phiPool[at], d) : max(phiPool[at], -d);
        phiPool[at] = clamp(p, -PHI_FAR, PHI_FAR);
    }
}
