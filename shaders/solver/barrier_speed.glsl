// Barriers: spheres the operator closed to the surface for the rest of the run (a leak's neck).
// Inside one the speed is negative whatever the scan says, and at least barrierHold, which the
// host sets so that alpha * hold outweighs the curvature term's pull: the front recedes from a
// barrier and never crosses it. CPU twin: barrierSpeed() in app/solver/barriers.hpp.
#ifndef MAX_BARRIERS
#define MAX_BARRIERS 16
#endif
uniform int barrierCount;
uniform vec4 barriers[MAX_BARRIERS]; // centre (voxel indices), radius (voxels)
uniform float barrierHold;

float barrierSpeed(ivec3 voxel, float dataSpeed) {
    vec3 p = vec3(voxel);
    for (int n = 0; n < barrierCount; ++n) {
        vec3 q = p - barriers[n].xyz;
        if (dot(q, q) <= barriers[n].w * barriers[n].w) {
            return -max(abs(dataSpeed), barrierHold);
        }
    }
    return dataSpeed;
}
