#version 310 es
// The expander must keep every line of a shader whose comment holds an unmatched bracket
// (CMake's lists do not split at ';' inside brackets): joined, the #endif below would vanish
// into the comment.
layout(local_size_x = 1) in;
layout(std430, binding = 0) buffer Out { float values[]; };
#if 1
float clamped(float x) { return clamp(x, 0.0, 1.0); } // onto [0, 1)
#endif
void main() {
    values[0] = clamped(2.0);
}
