#version 310 es
// An R32F 3D texture's values into a buffer, i fastest, for the host to read through
// gpu::readBufferBytes: the one way back from the GPU for every texture a check or a test
// compares with its CPU twin (gpu/texture_readback.hpp). Slabs of slices from zOffset keep each
// dispatch within the 65535 groups a dimension allows.
precision highp float;
precision highp int;
precision highp sampler3D;

#include "common/bindings.h"

layout(local_size_x = 4, local_size_y = 4, local_size_z = 4) in;

layout(binding = READ_VOLUME_UNIT) uniform highp sampler3D source;
layout(std430, binding = READ_VOLUME_BINDING) writeonly buffer Values {
    float values[];
};
uniform ivec3 volumeDims;
uniform int zOffset;

void main() {
    ivec3 v = ivec3(gl_GlobalInvocationID) + ivec3(0, 0, zOffset);
    if (any(greaterThanEqual(v, volumeDims))) {
        return;
    }
    values[v.x + volumeDims.x * (v.y + volumeDims.y * v.z)] = texelFetch(source, v, 0).r;
}
