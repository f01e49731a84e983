// Shared by the renderer's compute shaders: the scan texture, window/level and the level set
// read straight from the solver's brick pool (common/brick_pool.glsl).
precision highp sampler3D;
precision highp sampler2D;

#include "common/brick_pool.glsl"

layout(rgba8, binding = VIEW_OUT_IMAGE_UNIT) uniform writeonly highp image2D outImage;
layout(binding = VIEW_SCAN_UNIT) uniform sampler3D scanTex; // intensity, linear filtering
uniform vec2 scanToNormalised; // texture value -> normalised intensity: v * x + y (ScanTexture)

uniform ivec2 outSize;
uniform ivec2 firstPixel;   // the part this dispatch draws starts here (ViewParams::region)
uniform int hasSurface;     // 0: no level set bound
uniform vec2 windowRange;   // normalised intensity at black, 1 / window width

const vec3 CONTOUR_YELLOW = vec3(1.0, 0.92, 0.0);

// Scan intensity at a continuous voxel-index position (voxel centres at integers).
float scanAt(vec3 p) {
    return texture(scanTex, (p + 0.5) / vec3(volumeDims)).r * scanToNormalised.x + scanToNormalised.y;
}

float windowed(float v) {
    return clamp((v - windowRange.x) * windowRange.y, 0.0, 1.0);
}

// Whether phi is constant around p without a pool read: every corner of p's trilinear cell
// lies in one brick stored as inside/outside. That brick in `brick`, its sign in `inside`.
bool constantBrickAt(vec3 p, out ivec3 brick, out bool inside) {
    brick = clamp(ivec3(floor(p)), ivec3(0), volumeDims - 1) / BRICK_SIZE;
    ivec3 hi = clamp(ivec3(floor(p)) + 1, ivec3(0), volumeDims - 1) / BRICK_SIZE;
    if (brick != hi) {
        return false;
    }
    uint slot = pageTable[brickIndex(brick)];
    inside = slot == BRICK_INSIDE;
    return slot == BRICK_INSIDE || slot == BRICK_OUTSIDE;
}

// phi, with a shortcut for constant bricks (constantBrickAt).
float phiFast(vec3 p) {
    ivec3 brick;
    bool inside;
    if (constantBrickAt(p, brick, inside)) {
        return inside ? -PHI_FAR : PHI_FAR;
    }
    return phiTrilinear(p);
}

// The level set as a cubic B-spline over phi's voxels (a light smoothing, [1 4 1] / 6 per axis
// at the voxels): continuous in value, gradient and curvature, where trilinear phi has a kink
// at every voxel plane. Shading with its gradient makes a sphere look round and thick slices
// show no terraces; the zero crossing is refined on it too. 64 pool reads, so only at the
// surface, never per sample. The gradient is per voxel index.
float phiSmooth(vec3 p, out vec3 grad) {
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
        float c = phiAt(b + o);
        vec3 wo = vec3(w[o.x].x, w[o.y].y, w[o.z].z);
        vec3 dw = vec3(d[o.x].x, d[o.y].y, d[o.z].z);
        value += wo.x * wo.y * wo.z * c;
        grad += vec3(dw.x * wo.y * wo.z, wo.x * dw.y * wo.z, wo.x * wo.y * dw.z) * c;
    }
    return value;
}
