#version 310 es
// The 3D view's gradient texture, once per scan: at each voxel, in normalised intensity per
// voxel, the difference [-1 -2 0 2 1] / 8 along each axis (the central difference of the scan
// smoothed by [1 2 1] / 4 along that axis), and in alpha the normalised intensity itself, so the
// ray caster fetches both at once. The plain central difference made rings on the
// built-in sample's head seen from above, one per 1.5 mm slice: on a boundary about a voxel
// wide, the largest gradient it finds swings by up to half with where the boundary falls
// between two voxels, and the transfer function's gradient axis turns that into opacity. The
// wider difference swings much less. Trilinear interpolation of these differences equals the
// same difference of the trilinearly interpolated scan (the weights are the same at every
// offset), which is what the ray caster takes per sample without this texture.
precision highp float;
precision highp sampler3D;
precision highp image3D;

#include "common/bindings.h"

layout(local_size_x = 4, local_size_y = 4, local_size_z = 4) in;

layout(binding = VIEW_SCAN_UNIT) uniform sampler3D scanTex;
// rgba32f, or rgba16f where the full floats would exceed the memory budget (GradientTexture).
#ifndef GRADIENT_IMAGE_FORMAT
#define GRADIENT_IMAGE_FORMAT rgba16f
#endif
layout(GRADIENT_IMAGE_FORMAT, binding = VIEW_GRADIENT_IMAGE_UNIT) uniform writeonly image3D gradientOut;
uniform ivec3 volumeDims;
uniform vec2 toNormalised; // display-texture value v -> normalised intensity: v * x + y

float at(ivec3 v) {
    return texelFetch(scanTex, clamp(v, ivec3(0), volumeDims - 1), 0).r;
}

void main() {
    ivec3 v = ivec3(gl_GlobalInvocationID);
    if (any(greaterThanEqual(v, volumeDims))) {
        return;
    }
    vec3 g = vec3(0.0);
    for (int a = 0; a < 3; ++a) {
        ivec3 e = ivec3(0);
        e[a] = 1;
        g[a] = (2.0 * (at(v + e) - at(v - e)) + at(v + 2 * e) - at(v - 2 * e)) / 8.0;
    }
    g *= toNormalised.x;
    imageStore(gradientOut, v, vec4(g, at(v) * toNormalised.x + toNormalised.y));
}
