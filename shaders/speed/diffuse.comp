#version 310 es
// One step of gradient anisotropic diffusion (Perona-Malik), the smoothing the speed reads
// instead of the raw scan (docs/speed.md):
//   I' = I + dt * sum over the 6 face neighbours n of c(I_n - I) * (I_n - I),
//   c(d) = exp(-(d / K)^2)
// Differences much larger than the conductance K (an edge) barely diffuse, smaller ones (noise)
// diffuse like the heat equation. dt = 0.0625 = 1 / 2^(N+1) in 3D, ITK's stability limit for
// this explicit scheme. The conductance comes from the face difference alone (the original
// Perona-Malik scheme), not from ITK's full-gradient estimate at the half voxel: one fetch per
// neighbour, and the same edge-stopping behaviour. Borders repeat the edge voxel (zero flux).
precision highp float;
precision highp sampler3D;
precision highp image3D;

#include "common/bindings.h"

layout(local_size_x = 4, local_size_y = 4, local_size_z = 4) in;

layout(binding = SPEED_SOURCE_UNIT) uniform sampler3D source;
layout(r32f, binding = SPEED_OUT_IMAGE_UNIT) uniform writeonly image3D smoothed;
uniform ivec3 volumeDims;
uniform float timeStep;
uniform float invConductance; // 1 / K

float at(ivec3 v) {
    return texelFetch(source, clamp(v, ivec3(0), volumeDims - 1), 0).r;
}

float flux(float centre, ivec3 n) {
    float d = at(n) - centre;
    float s = d * invConductance;
    return exp(-s * s) * d;
}

void main() {
    ivec3 v = ivec3(gl_GlobalInvocationID);
    if (any(greaterThanEqual(v, volumeDims))) {
        return;
    }
    float c = at(v);
    float sum = flux(c, v + ivec3(1, 0, 0)) + flux(c, v - ivec3(1, 0, 0)) +
                flux(c, v + ivec3(0, 1, 0)) + flux(c, v - ivec3(0, 1, 0)) +
                flux(c, v + ivec3(0, 0, 1)) + flux(c, v - ivec3(0, 0, 1));
    imageStore(smoothed, v, vec4(c + timeStep * sum, 0.0, 0.0, 0.0));
}
