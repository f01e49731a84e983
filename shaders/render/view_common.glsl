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
