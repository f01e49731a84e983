#version 310 es
// The logical screen onto the display, turned by the panel's mounting (config display.rotation).
// One triangle covers the display; `physical` is the display position with (0, 0) at its top
// left and (1, 1) at its bottom right.
out vec2 physical;

void main() {
    vec2 corner = vec2(float((gl_VertexID << 1) & 2), float(gl_VertexID & 2)); // (0,0) (2,0) (0,2)
    gl_Position = vec4(corner * 2.0 - 1.0, 0.0, 1.0);
    physical = vec2(corner.x, 1.0 - corner.y);
}
