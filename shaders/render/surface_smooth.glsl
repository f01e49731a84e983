// The 3D view's surface between voxels (render/raycast.comp, after the march found the cell
// where phi changes sign): a smooth reconstruction of the level set to refine the crossing on
// and to shade with, or, where the level set no longer says where between two voxels the
// boundary lies, of the data term whose zero crossing it is.
//
// Why the data term: at convergence the data term (hundreds per voxel in the scan's units)
// drives phi to its clamp on both sides of the front (-3.9 | +3.8 across an edge), so phi is a
// step whose zero sits half-way between voxel centres, as a mask's does, and a sphere shows
// its voxels and thick slices their terraces. The scan still holds the boundary between the
// voxels (partial volume), and the speed's zero crossing, D = 0, is where the front stopped.
// Mixing the two voxel by voxel (D's distance where it agrees with phi) was tried first: a
// voxel where they disagree (a partial-volume voxel whose centre lies inside but most of it
// outside) kept phi's -3.9 among D's fractions and raised a bump around it. So one pixel's
// reconstruction is all phi or all D, chosen by its cell (dataPlacesSurface). The surface's
// outline stays phi's (the march finds it on trilinear phi); its shading and its place along
// the ray follow D. The includer defines DATA_SPEED_INTENSITY_UNIT and DATA_SPEED_FACTOR_UNIT.
#include "speed/data_speed.glsl"

// 1: the level set was moved by this data term (the solver's own, T and eps in force), so its
// zero crossing places the surface; 0: phi alone (a mask from elsewhere, no speed).
uniform int surfaceFromData;

// A distance changes by about one per voxel, so a cell that holds its zero has a corner nearer
// than this; a cell whose corners are all as far is a step's.
const float STEP_PHI = 1.0;

// D in the voxel's range (texelFetch has no border).
float dataSpeedClamped(ivec3 v) {
    return dataSpeed(clamp(v, ivec3(0), volumeDims - 1));
}

// Whether the surface in p's cell is drawn from the data term: phi is a step there (every
// corner at least STEP_PHI from zero). Otherwise phi (a front still moving, a distance from a
// seed or a mask) is drawn. A step where D has no crossing (a front held by a barrier, the
// curvature term or a reach) is caught by the ray's refinement, which then falls back to phi.
bool dataPlacesSurface(vec3 p) {
    if (surfaceFromData == 0) {
        return false;
    }
    ivec3 b = ivec3(floor(p));
    float nearest = PHI_FAR;
    for (int n = 0; n < 8; ++n) {
        nearest = min(nearest, abs(phiAt(b + ivec3(n & 1, (n >> 1) & 1, n >> 2))));
    }
    return nearest >= STEP_PHI;
}

// One voxel of the reconstruction: phi, or -D (negative inside, as phi; the crossing and the
// normal do not depend on its scale).
float surfaceValue(ivec3 v, bool fromData) {
    return fromData ? -dataSpeedClamped(v) : phiAt(v);
}

// The reconstruction as a cubic B-spline over the voxels' values (a light smoothing, [1 4 1] / 6
// per axis at the voxels): continuous in value, gradient and curvature, where trilinear phi has
// a kink at every voxel plane. Shading with its gradient makes a sphere look round; the zero
// crossing is refined on it too. 64 pool (or scan) reads, so only at the surface, never per
// sample. The gradient is per voxel index.
float phiSmooth(vec3 p, bool fromData, out vec3 grad) {
    vec3 base = floor(p);
    vec3 f = p - base;
    vec3 g = 1.0 - f;
    vec3 f2 = f * f;
    // The four B-spline weights per axis and their derivatives.
    vec3 w[4];
    w[0] = g * g * g / 6.0;
    w[1] = (3.0 * f2 * f - 6.0 * f2 + 4.0) / 6.0;
    w[2] = (-3.0 * f2 * f + 3.0 * f2 + 3.0 * f + 1.0) / 6.0;
    w[3] = f2 * f / 6.0;
    vec3 d[4];
    d[0] = -0.5 * g * g;
    d[1] = 1.5 * f2 - 2.0 * f;
    d[2] = -1.5 * f2 + f + 0.5;
    d[3] = 0.5 * f2;
    ivec3 b = ivec3(base) - 1;
    float value = 0.0;
    grad = vec3(0.0);
    // One loop over the 64 voxels, not three nested ones: a compiler unrolls small constant
    // loops, and 64 inlined pool reads (per call site) took llvmpipe half a minute to compile.
    for (int n = 0; n < 64; ++n) {
        ivec3 o = ivec3(n & 3, (n >> 2) & 3, n >> 4);
        float c = surfaceValue(b + o, fromData);
        vec3 wo = vec3(w[o.x].x, w[o.y].y, w[o.z].z);
        vec3 dw = vec3(d[o.x].x, d[o.y].y, d[o.z].z);
        value += wo.x * wo.y * wo.z * c;
        grad += vec3(dw.x * wo.y * wo.z, wo.x * dw.y * wo.z, wo.x * wo.y * dw.z) * c;
    }
    return value;
}
