#version 310 es
// Accepted: every invocation reaches both barriers; returns in helpers and after the last
// barrier are fine.
layout(local_size_x = 64) in;
layout(std430, binding = 0) buffer Data { uint data[]; };
shared uint total;
uniform uint count;

uint load(uint i) {
    if (i >= count) {
        return 0u;
    }
    return data[i];
}

void main() {
    bool hasWork = gl_WorkGroupID.x < count;
    if (gl_LocalInvocationIndex == 0u) {
        total = 0u;
    }
    barrier();
    if (hasWork) {
        atomicAdd(total, load(gl_GlobalInvocationID.x));
    }
    barrier();
    if (!hasWork) {
        return;
    }
    data[gl_GlobalInvocationID.x] = total;
}
