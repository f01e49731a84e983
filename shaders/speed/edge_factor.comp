#version 310 es
// The edge-stopping factor g = 1 / (1 + (|grad I| / kappa)^2) of the edge speed
// g * (eps - |I - T|) (docs/speed.md): near 1 where the (smoothed) scan is flat, near 0 across
// an edge much steeper than kappa. Central differences in voxel units, like the level-set PDE;
// borders repeat the edge voxel.
precision highp float;
precision highp sampler3D;
precision highp image3D;

#include "common/bindings.h"

layout(local_size_x = 4, local_size_y = 4, local_size_z = 4) in;

layout(binding = SPEED_SOURCE_UNIT) uniform sampler3D intensity;
layout(r32f, binding = SPEED_OUT_IMAGE_UNIT) uniform writeonly image3D factor;
uniform ivec3 volumeDims;
uniform float invKappa; // 1 / kappa, kappa in real units per voxel

float at(ivec3 v) {
    return texelFetch(intensity, clamp(v, ivec3(0), volumeDims - 1), 0).r;
}

void main() {
    ivec3 v = ivec3(gl_GlobalInvocationID);
    if (any(greaterThanEqual(v, volumeDims))) {
        return;
    }
    vec3 g = 0.5 * vec3(at(v + ivec3(1, 0, 0)) - at(v - ivec3(1, 0, 0)),
                        at(v + ivec3(0, 1, 0)) - at(v - ivec3(0, 1, 0)),
                        at(v + ivec3(0, 0, 1)) - at(v - ivec3(0, 0, 1)));
    float s = length(g) * invKappa;
    imageStore(factor, v, vec4(1.0 / (1.0 + s * s), 0.0, 0.0, 0.0));
}
