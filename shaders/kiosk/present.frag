#version 310 es
precision highp float;

layout(binding = 0) uniform sampler2D logicalScreen; // GL rows: bottom of the screen first
// Clockwise quarter turns the logical screen takes to appear upright on the display.
uniform int quarterTurns;

in vec2 physical;
out vec4 colour;

void main() {
    // The logical position (top-left origin) shown at this display position.
    vec2 s;
    if (quarterTurns == 1) {
        s = vec2(physical.y, 1.0 - physical.x);
    } else if (quarterTurns == 2) {
        s = vec2(1.0 - physical.x, 1.0 - physical.y);
    } else if (quarterTurns == 3) {
        s = vec2(1.0 - physical.y, physical.x);
    } else {
        s = physical;
    }
    colour = texture(logicalScreen, vec2(s.x, 1.0 - s.y));
}
