#version 310 es
// Smoke test of the compute path: out[i] = in[i] * in[i] + offset.
layout(local_size_x = 64) in;

layout(std430, binding = 0) readonly buffer Input { float values[]; } src;
layout(std430, binding = 1) writeonly buffer Output { float values[]; } dst;

uniform float offset;
uniform uint count;

void main() {
    uint i = gl_GlobalInvocationID.x;
    if (i < count) {
        dst.values[i] = src.values[i] * src.values[i] + offset;
    }
}
