// Barriers: spheres the operator fixed on one side of the surface for the rest of the run
// (model::Barrier). A blocking one (radius w > 0: a leak's neck, an erase that sticks) makes the
// speed negative whatever the scan says; a keeping one (w < 0: an added correction) makes it
// positive. Either way at least barrierHold, which the host sets so that alpha * hold outweighs
// the curvature term's pull: the front recedes from a blocking sphere and never crosses it, and
// never leaves a keeping one. Where spheres overlap, the newest decides (the operator's latest
// word). The host side: LevelSetSolver::uploadBarriers (app/solver/level_set_edits.cpp).
#ifndef MAX_BARRIERS
#define MAX_BARRIERS 16
#endif
uniform int barrierCount;
uniform vec4 barriers[MAX_BARRIERS]; // centre (voxel indices), signed radius (voxels)
uniform float barrierHold;

float barrierSpeed(ivec3 voxel, float dataSpeed) {
    vec3 p = vec3(voxel);
    for (int n = barrierCount - 1; n >= 0; --n) {
        vec3 q = p - barriers[n].xyz;
        float w = barriers[n].w;
        if (dot(q, q) <= w * w) {
            float held = max(abs(dataSpeed), barrierHold);
            return w < 0.0 ? held : -held;
        }
    }
    return dataSpeed;
}
