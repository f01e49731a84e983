#version 310 es
// Rejected: groups past the list leave before the barrier the others wait at.
layout(local_size_x = 64) in;
layout(std430, binding = 0) buffer Data { uint data[]; };
shared uint total;
uniform uint count;

void main() {
    if (gl_WorkGroupID.x >= count) {
        return; // a "return" in a comment; and barrier() in one too
    }
    total = 0u;
    barrier();
    atomicAdd(total, data[gl_GlobalInvocationID.x]);
    barrier();
    data[gl_GlobalInvocationID.x] = total;
}
