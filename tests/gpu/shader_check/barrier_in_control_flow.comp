#version 310 es
// Rejected: a barrier only some groups reach.
layout(local_size_x = 64) in;
layout(std430, binding = 0) buffer Data { uint data[]; };
shared uint total;
uniform uint count;

void main() {
    bool hasWork = gl_WorkGroupID.x < count;
    total = 0u;
    if (hasWork) {
        barrier();
    }
    data[gl_GlobalInvocationID.x] = total;
}
