#version 310 es
// Rejected: a return between two barriers, inside nested blocks.
layout(local_size_x = 64) in;
layout(std430, binding = 0) buffer Data { uint data[]; };
shared uint total;

void main() {
    total = 0u;
    barrier();
    for (int i = 0; i < 2; ++i) {
        if (data[gl_LocalInvocationIndex] == 0u) {
            return;
        }
    }
    atomicAdd(total, 1u);
    barrier();
    data[gl_GlobalInvocationID.x] = total;
}
