#version 310 es
// The 3D view's gradient texture, once per scan: the central difference of the scan at each
// voxel, in normalised intensity per voxel. Trilinear interpolation of these differences equals
// the central difference of the trilinearly interpolated scan one voxel either side (the
// weights are the same for p + e and p - e), which is what the ray caster took with six fetches
// per sample.
precision highp float;
precision highp sampler3D;
precision highp image3D;

#include "common/bindings.h"

layout(local_size_x = 4, local_size_y = 4, local_size_z = 4) in;

layout(binding = VIEW_SCAN_UNIT) uniform sampler3D scanTex;
layout(rgba16f, binding = VIEW_GRADIENT_IMAGE_UNIT) uniform writeonly image3D gradientOut;
uniform ivec3 volumeDims;
uniform float toNormalised; // display-texture value difference -> normalised intensity

float at(ivec3 v) {
    return texelFetch(scanTex, clamp(v, ivec3(0), volumeDims - 1), 0).r;
}

void main() {
    ivec3 v = ivec3(gl_GlobalInvocationID);
    if (any(greaterThanEqual(v, volumeDims))) {
        return;
    }
    vec3 g = 0.5 * toNormalised *
             vec3(at(v + ivec3(1, 0, 0)) - at(v - ivec3(1, 0, 0)),
                  at(v + ivec3(0, 1, 0)) - at(v - ivec3(0, 1, 0)),
                  at(v + ivec3(0, 0, 1)) - at(v - ivec3(0, 0, 1)));
    imageStore(gradientOut, v, vec4(g, 0.0));
}
