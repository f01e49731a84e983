#version 310 es
// Slice views: the scan (window/level) or the speed function's data term D, the solver's own
// (speed/data_speed.glsl: threshold, edge or classify; positive green, negative blue), on a
// plane of constant voxel index, the level set's zero crossing as a yellow contour read live
// from the brick pool, and orientation letters. Row 0 of the image is the top of the picture.
layout(local_size_x = 8, local_size_y = 8) in;

#include "render/view_common.glsl"
#define DATA_SPEED_INTENSITY_UNIT VIEW_SPEED_INTENSITY_UNIT
#define DATA_SPEED_FACTOR_UNIT VIEW_SPEED_FACTOR_UNIT
#include "speed/data_speed.glsl"

uniform vec3 sliceOrigin;  // voxel-index position of pixel (0, 0)'s centre
uniform vec3 sliceAxisU;   // voxel-index step per pixel to the right
uniform vec3 sliceAxisV;   // voxel-index step per pixel downwards
uniform int showSpeed;
uniform float speedScale;  // |D| at full colour: eps, or 1 for classify's P(in) - P(out)
uniform int showContour;
uniform ivec4 labelGlyphs; // left, right, top, bottom: 0..5 = A I L P R S, -1 none
uniform int labelScale;

// 5x7 bitmaps, one row per entry, bit 4 = leftmost column.
const int FONT[42] = int[42](
    14, 17, 17, 31, 17, 17, 17,  // A
    14, 4, 4, 4, 4, 4, 14,       // I
    16, 16, 16, 16, 16, 16, 31,  // L
    30, 17, 17, 30, 16, 16, 16,  // P
    30, 17, 17, 30, 20, 18, 17,  // R
    15, 16, 16, 14, 1, 1, 30);   // S

bool glyphCovers(int glyph, ivec2 topLeft, ivec2 pixel) {
    if (glyph < 0) {
        return false;
    }
    ivec2 local = (pixel - topLeft) / labelScale;
    if (pixel.x < topLeft.x || pixel.y < topLeft.y || local.x >= 5 || local.y >= 7) {
        return false;
    }
    return ((FONT[glyph * 7 + local.y] >> (4 - local.x)) & 1) != 0;
}

bool labelAt(ivec2 pixel) {
    int s = labelScale;
    int margin = 3 * s;
    ivec2 glyph = ivec2(5, 7) * s;
    ivec2 mid = (outSize - glyph) / 2;
    return glyphCovers(labelGlyphs.x, ivec2(margin, mid.y), pixel) ||
           glyphCovers(labelGlyphs.y, ivec2(outSize.x - margin - glyph.x, mid.y), pixel) ||
           glyphCovers(labelGlyphs.z, ivec2(mid.x, margin), pixel) ||
           glyphCovers(labelGlyphs.w, ivec2(mid.x, outSize.y - margin - glyph.y), pixel);
}

// D between voxel centres: the voxels' values blended as the scan's are (the solver reads D at
// voxels only).
float speedAt(vec3 p) {
    vec3 q = clamp(p, vec3(0.0), vec3(volumeDims - 1));
    ivec3 b = ivec3(floor(q));
    ivec3 c = min(b + 1, volumeDims - 1);
    vec3 f = q - vec3(b);
    float x00 = mix(dataSpeed(b), dataSpeed(ivec3(c.x, b.y, b.z)), f.x);
    float x10 = mix(dataSpeed(ivec3(b.x, c.y, b.z)), dataSpeed(ivec3(c.x, c.y, b.z)), f.x);
    float x01 = mix(dataSpeed(ivec3(b.x, b.y, c.z)), dataSpeed(ivec3(c.x, b.y, c.z)), f.x);
    float x11 = mix(dataSpeed(ivec3(b.x, c.y, c.z)), dataSpeed(c), f.x);
    return mix(mix(x00, x10, f.y), mix(x01, x11, f.y), f.z);
}

bool inVolume(vec3 p) {
    return all(greaterThanEqual(p, vec3(-0.5))) && all(lessThan(p, vec3(volumeDims) - 0.5));
}

void main() {
    ivec2 pixel = ivec2(gl_GlobalInvocationID.xy) + firstPixel;
    if (pixel.x >= outSize.x || pixel.y >= outSize.y) {
        return;
    }
    vec3 p = sliceOrigin + float(pixel.x) * sliceAxisU + float(pixel.y) * sliceAxisV;
    vec3 colour = vec3(0.0);
    if (inVolume(p)) {
        float v = scanAt(p);
        float grey = windowed(v);
        colour = vec3(grey);
        if (showSpeed != 0) {
            float d = speedAt(p);
            float strength = 0.45 + 0.55 * clamp(abs(d) / speedScale, 0.0, 1.0);
            vec3 tint = d > 0.0 ? vec3(0.1, 0.85, 0.2) : vec3(0.2, 0.3, 0.95);
            colour = mix(vec3(grey), tint * strength, 0.75);
        }
        if (hasSurface != 0 && showContour != 0) {
            // A pixel is on the contour when phi changes sign towards its right or lower
            // neighbour: a one-pixel line along the zero crossing.
            bool here = phiTrilinear(p) <= 0.0;
            bool right = phiTrilinear(p + sliceAxisU) <= 0.0;
            bool below = phiTrilinear(p + sliceAxisV) <= 0.0;
            if (here != right || here != below) {
                colour = CONTOUR_YELLOW;
            }
        }
    }
    if (labelAt(pixel)) {
        colour = vec3(1.0, 0.55, 0.1);
    }
    imageStore(outImage, pixel, vec4(colour, 1.0));
}
