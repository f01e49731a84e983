#version 310 es
// 3D view: ray casting of the scan with a 2D transfer function (intensity x gradient
// magnitude), lighting, early ray termination and empty-space skipping, plus the level-set
// surface read from the brick pool (first crossing of phi = 0), the surface as region of
// interest, and a clipping plane textured with the scan with its surface intersection in
// yellow. One invocation per pixel; row 0 of the image is the top of the picture.
layout(local_size_x = 8, local_size_y = 8) in;

#include "render/view_common.glsl"

layout(binding = VIEW_TF_LUT_UNIT) uniform sampler2D tfLut;      // RGBA8, intensity x gradient bins
layout(binding = VIEW_SKIP_GRID_UNIT) uniform sampler3D skipGrid;   // RG16F block min/max
layout(binding = VIEW_OCCUPANCY_UNIT) uniform sampler2D occupancy;  // R32F, 257 prefix counts of occupied bins

uniform vec3 eyeIndex;       // camera eye in voxel-index space
uniform mat3 worldToIndex;   // inverse of direction * diag(spacing)
uniform vec3 camForward;     // world
uniform vec3 camRight;       // world, scaled by tan(fov / 2) * aspect
uniform vec3 camUp;          // world, scaled by tan(fov / 2)
uniform float stepMm;
uniform float gradientScale; // TF gradient axis: |grad| per voxel / gradientScale
uniform int surfaceMode;     // 0 hidden, 1 opaque, 2 translucent
uniform int roiMode;         // 0 off, 1 inside only, 2 dim outside
uniform float dimFactor;
uniform int clipEnabled;
uniform vec4 clipPlane;      // n . p = d in voxel indices; n . p > d is cut away
uniform float lineWidth;     // |phi| below this on the plane is drawn yellow (voxels)

const vec3 SURFACE_COLOUR = vec3(0.95, 0.62, 0.25);
const float SURFACE_TRANSLUCENT_ALPHA = 0.35;
const int TF_BINS = 256;

vec2 boxHits(vec3 o, vec3 d, vec3 lo, vec3 hi) {
    vec3 inv = 1.0 / d;
    vec3 a = (lo - o) * inv;
    vec3 b = (hi - o) * inv;
    vec3 tmin = min(a, b);
    vec3 tmax = max(a, b);
    return vec2(max(max(tmin.x, tmin.y), tmin.z), min(min(tmax.x, tmax.y), tmax.z));
}

bool blockOccupied(vec3 p, out vec3 blockLo) {
    ivec3 grid = textureSize(skipGrid, 0);
    ivec3 b = clamp(ivec3(floor((p + 0.5) / 8.0)), ivec3(0), grid - 1);
    blockLo = vec3(b * 8) - 0.5;
    vec2 mm = texelFetch(skipGrid, b, 0).rg;
    int lo = clamp(int(floor(mm.x * float(TF_BINS - 1))), 0, TF_BINS - 1);
    int hi = clamp(int(ceil(mm.y * float(TF_BINS - 1))), 0, TF_BINS - 1);
    return texelFetch(occupancy, ivec2(hi + 1, 0), 0).r - texelFetch(occupancy, ivec2(lo, 0), 0).r > 0.5;
}

vec3 shade(vec3 base, vec3 gradIndex, vec3 rayDir) {
    vec3 n = transpose(worldToIndex) * gradIndex; // index-space gradient to world
    float len = length(n);
    if (len < 1e-6) {
        return base;
    }
    n /= len;
    float diffuse = abs(dot(n, rayDir));                  // headlight, two-sided
    float specular = pow(diffuse, 24.0);
    return base * (0.25 + 0.75 * diffuse) + vec3(0.25 * specular);
}

void composite(inout vec4 acc, vec3 colour, float alpha) {
    acc.rgb += (1.0 - acc.a) * alpha * colour;
    acc.a += (1.0 - acc.a) * alpha;
}

void main() {
    ivec2 pixel = ivec2(gl_GlobalInvocationID.xy) + firstPixel;
    if (pixel.x >= outSize.x || pixel.y >= outSize.y) {
        return;
    }
    vec2 ndc = vec2((float(pixel.x) + 0.5) / float(outSize.x) * 2.0 - 1.0,
                    1.0 - (float(pixel.y) + 0.5) / float(outSize.y) * 2.0);
    vec3 rayWorld = normalize(camForward + ndc.x * camRight + ndc.y * camUp);
    vec3 dir = worldToIndex * rayWorld; // voxels per millimetre along the ray
    vec3 origin = eyeIndex;

    vec2 span = boxHits(origin, dir, vec3(-0.5), vec3(volumeDims) - 0.5);
    span.x = max(span.x, 0.0);
    bool atPlane = false;
    if (clipEnabled != 0) {
        float nd = dot(clipPlane.xyz, dir);
        float no = dot(clipPlane.xyz, origin);
        if (abs(nd) < 1e-9) {
            if (no > clipPlane.w) {
                span = vec2(1.0, 0.0);
            }
        } else {
            float tc = (clipPlane.w - no) / nd;
            if (nd > 0.0) {
                span.y = min(span.y, tc);
            } else if (tc > span.x) {
                span.x = tc;
                atPlane = true;
            }
        }
    }
    vec4 acc = vec4(0.0);
    if (span.x < span.y) {
        if (atPlane) {
            // The cut face: the scan under window/level, and the surface's trace in yellow.
            vec3 p = origin + span.x * dir;
            vec3 colour = vec3(windowed(scanAt(p)));
            if (hasSurface != 0 && abs(phiTrilinear(p)) < lineWidth) {
                colour = CONTOUR_YELLOW;
            }
            acc = vec4(colour, 1.0);
        } else {
            // A fixed per-pixel offset of the sample lattice (interleaved gradient noise) turns
            // wood-grain aliasing into fine, deterministic noise.
            float jitter = fract(52.9829189 * fract(dot(vec2(pixel), vec2(0.06711056, 0.00583715))));
            float t = span.x + jitter * stepMm;
            float prevPhi = hasSurface != 0 ? phiFast(origin + t * dir) : 1.0;
            for (int guard = 0; guard < 16384 && t < span.y; ++guard) {
                vec3 p = origin + t * dir;
                float phi = hasSurface != 0 ? phiFast(p) : 1.0;
                if (hasSurface != 0 && surfaceMode != 0 && (phi <= 0.0) != (prevPhi <= 0.0)) {
                    // Refine the crossing between the previous sample and this one.
                    float a = t - stepMm;
                    float b = t;
                    float fa = prevPhi;
                    for (int i = 0; i < 6; ++i) {
                        float m = 0.5 * (a + b);
                        float fm = phiTrilinear(origin + m * dir);
                        if ((fm <= 0.0) == (fa <= 0.0)) {
                            a = m;
                            fa = fm;
                        } else {
                            b = m;
                        }
                    }
                    vec3 hit = origin + 0.5 * (a + b) * dir;
                    vec3 c = shade(SURFACE_COLOUR, phiGradient(hit), rayWorld);
                    composite(acc, c, surfaceMode == 1 ? 1.0 : SURFACE_TRANSLUCENT_ALPHA);
                    if (acc.a > 0.98) {
                        break;
                    }
                }
                prevPhi = phi;
                vec3 blockLo;
                bool blockUsed = blockOccupied(p, blockLo);
                // ROI inside: nothing of the scan outside the surface.
                bool occupied = blockUsed && !(hasSurface != 0 && roiMode == 1 && phi > 0.0);
                float v = occupied ? scanAt(p) : 0.0;
                if (occupied) {
                    // The value alone may already rule the sample out (no gradient needed).
                    float bin = v * float(TF_BINS - 1);
                    int lo = clamp(int(floor(bin)), 0, TF_BINS - 1);
                    int hi = clamp(int(ceil(bin)), 0, TF_BINS - 1);
                    occupied = texelFetch(occupancy, ivec2(hi + 1, 0), 0).r -
                                   texelFetch(occupancy, ivec2(lo, 0), 0).r > 0.5;
                }
                if (occupied) {
                    vec3 g = 0.5 * vec3(scanAt(p + vec3(1, 0, 0)) - scanAt(p - vec3(1, 0, 0)),
                                        scanAt(p + vec3(0, 1, 0)) - scanAt(p - vec3(0, 1, 0)),
                                        scanAt(p + vec3(0, 0, 1)) - scanAt(p - vec3(0, 0, 1)));
                    float gm = clamp(length(g) / gradientScale, 0.0, 1.0);
                    vec2 uv = (vec2(v, gm) * vec2(float(TF_BINS - 1), 31.0) + 0.5) /
                              vec2(float(TF_BINS), 32.0);
                    vec4 tf = texture(tfLut, uv);
                    float alpha = 1.0 - pow(1.0 - min(tf.a, 0.999), stepMm);
                    if (hasSurface != 0 && phi > 0.0) {
                        alpha *= roiMode == 1 ? 0.0 : (roiMode == 2 ? dimFactor : 1.0);
                    }
                    if (alpha > 0.001) {
                        composite(acc, shade(tf.rgb, g, rayWorld), alpha);
                        if (acc.a > 0.98) {
                            break;
                        }
                    }
                } else if (!blockUsed && hasSurface == 0) {
                    // Nothing to see in this block: jump to where the ray leaves it, keeping
                    // samples on the same lattice.
                    vec2 bh = boxHits(origin, dir, blockLo, blockLo + 8.0);
                    float skip = max(0.0, ceil((bh.y - t) / stepMm) - 1.0);
                    t += skip * stepMm;
                    prevPhi = 1.0;
                }
                t += stepMm;
            }
        }
    }
    imageStore(outImage, pixel, vec4(acc.rgb, 1.0));
}
