#version 310 es
// 3D view: ray casting of the scan with a 2D transfer function (intensity x gradient
// magnitude), lighting, early ray termination and empty-space skipping, plus the level-set
// surface read from the brick pool (first crossing of phi = 0), the surface as region of
// interest, the other structures as opaque surfaces in their colours (a label per voxel), and
// a clipping plane textured with the scan with its surface intersection in yellow. One
// invocation per pixel; row 0 of the image is the top of the picture.

// 1: the second pass over the pixels whose ray hit an opaque surface (HAS_SURFACE only).
#ifndef SURFACE_PASS
#define SURFACE_PASS 0
#endif
#define SURFACE_PASS_GROUP 64
// GLES 3.1's least limit on work groups per dispatch: beyond it each invocation takes several
// hits (an 8192 x 8192 picture holds 1M groups' worth).
#define SURFACE_PASS_MAX_GROUPS 65535u
#if SURFACE_PASS
layout(local_size_x = SURFACE_PASS_GROUP) in;
#else
layout(local_size_x = 8, local_size_y = 8) in;
#endif

#include "render/view_common.glsl"
#include "render/render_bindings.h"

layout(binding = VIEW_TF_LUT_UNIT) uniform sampler2D tfLut;      // RGBA8, intensity x gradient bins
layout(binding = VIEW_SKIP_GRID_UNIT) uniform sampler3D skipGrid;   // R8 per block: may hold a visible sample
layout(binding = VIEW_OCCUPANCY_UNIT) uniform sampler2D occupancy;  // R32F 257x33 summed-area table of occupied bins

// 1: the scan's gradient comes from render/gradient.comp's texture (one fetch per sample);
// 0: differenced here from six fetches (a scan too large for the gradient texture).
#ifndef GRADIENT_TEXTURE
#define GRADIENT_TEXTURE 1
#endif
// 0: no level set bound. A separate program rather than a test of hasSurface in the loop: a
// software rasteriser pays for the surface's code in every sample otherwise (5x on llvmpipe).
#ifndef HAS_SURFACE
#define HAS_SURFACE 1
#endif
#if GRADIENT_TEXTURE
layout(binding = VIEW_GRADIENT_UNIT) uniform sampler3D gradientTex; // RGBA16F, normalised / voxel
#endif
// 1: other structures are drawn (app/render/structure_labels.hpp). A variant for the same
// reason as HAS_SURFACE: a session without others runs none of their code. 1 unless told, so
// that the build validates their code (the programs name every variant's defines).
#ifndef HAS_LABELS
#define HAS_LABELS 1
#endif
#if HAS_LABELS
layout(binding = VIEW_LABELS_UNIT) uniform highp usampler3D labels; // 0 none, n: colour n - 1
uniform vec3 labelColours[VIEW_MAX_STRUCTURE_LABELS];
#endif

uniform vec3 eyeIndex;       // camera eye in voxel-index space
uniform mat3 worldToIndex;   // inverse of direction * diag(spacing)
uniform vec3 camForward;     // world
uniform vec3 camRight;       // world, scaled by tan(fov / 2) * aspect
uniform vec3 camUp;          // world, scaled by tan(fov / 2)
uniform float stepMm;
uniform float skipBlock;     // voxels per side of a skipGrid block
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
const int TF_GRADIENT_BINS = 32;

vec2 boxHits(vec3 o, vec3 d, vec3 lo, vec3 hi) {
    vec3 inv = 1.0 / d;
    vec3 a = (lo - o) * inv;
    vec3 b = (hi - o) * inv;
    // Along an axis the ray does not move on, its slab holds all of the ray or none of it
    // (and 0 * inf, an origin on the slab's face, is not a number).
    bvec3 still = equal(d, vec3(0.0));
    bvec3 inSlab = bvec3(step(lo, o) * step(o, hi));
    a = mix(a, mix(vec3(1e30), vec3(-1e30), inSlab), still);
    b = mix(b, mix(vec3(-1e30), vec3(1e30), inSlab), still);
    vec3 tmin = min(a, b);
    vec3 tmax = max(a, b);
    return vec2(max(max(tmin.x, tmin.y), tmin.z), min(min(tmax.x, tmax.y), tmax.z));
}

// Any occupied transfer-function texel in intensity bins lo..hi, gradient bins 0..gHi
// (occupancyTable() in app/render/transfer_function.cpp).
bool occupiedIn(int lo, int hi, int gHi) {
    return texelFetch(occupancy, ivec2(hi + 1, gHi + 1), 0).r -
               texelFetch(occupancy, ivec2(lo, gHi + 1), 0).r > 0.5;
}

// Whether block b may hold a visible sample under this transfer function (decided per block
// on the host when it is baked: app/render/skip_grid.hpp).
bool blockOccupied(ivec3 b) {
    return texelFetch(skipGrid, b, 0).r > 0.5;
}

vec3 shade(vec3 base, vec3 gradIndex, vec3 rayDir) {
    vec3 n = transpose(worldToIndex) * gradIndex; // index-space gradient to world
    float len2 = dot(n, n);
    // Branch-free: a software rasteriser runs both sides of a branch for the whole SIMD group.
    float lit = len2 < 1e-12 ? 0.0 : 1.0;
    float diffuse = abs(dot(n, rayDir)) * inversesqrt(max(len2, 1e-12)); // headlight, two-sided
    // diffuse^24 by squaring: pow() is exp2(log2()) in software rasterisers.
    float d2 = diffuse * diffuse;
    float d8 = d2 * d2 * d2 * d2;
    float specular = d8 * d8 * d8;
    return mix(base, base * (0.25 + 0.75 * diffuse) + vec3(0.25 * specular), lit);
}

void composite(inout vec4 acc, vec3 colour, float alpha) {
    acc.rgb += (1.0 - acc.a) * alpha * colour;
    acc.a += (1.0 - acc.a) * alpha;
}

// The scan's gradient at p, per voxel index: render/gradient.comp's difference, from its
// texture or of the trilinear scan (the same by linearity).
vec3 scanGradient(vec3 p) {
#if GRADIENT_TEXTURE
    return texture(gradientTex, (p + 0.5) / vec3(volumeDims)).rgb;
#else
    vec3 g = vec3(0.0);
    for (int a = 0; a < 3; ++a) {
        vec3 e = vec3(0.0);
        e[a] = 1.0;
        g[a] = (2.0 * (scanAt(p + e) - scanAt(p - e)) + scanAt(p + 2.0 * e) - scanAt(p - 2.0 * e)) /
               8.0;
    }
    return g;
#endif
}

// The scan's sample at p, standing for `len` millimetres of the ray, composited into acc, its
// opacity scaled by `weight` (the region of interest); true once the ray is opaque.
bool addScanSample(inout vec4 acc, vec3 p, float len, float weight, vec3 rayWorld) {
#if GRADIENT_TEXTURE
    // The gradient texture holds the normalised intensity too: one fetch for both.
    vec4 sampled = texture(gradientTex, (p + 0.5) / vec3(volumeDims));
    float v = sampled.a;
    vec3 g = sampled.rgb;
#else
    float v = scanAt(p);
    // The value alone may already rule the sample out (no twelve fetches for the gradient). With
    // the gradient texture the lookup below costs no more, and an unoccupied value bin gives
    // zero opacity there too.
    float bin = v * float(TF_BINS - 1);
    if (!occupiedIn(clamp(int(floor(bin)), 0, TF_BINS - 1), clamp(int(ceil(bin)), 0, TF_BINS - 1),
                    TF_GRADIENT_BINS - 1)) {
        return false;
    }
    vec3 g = scanGradient(p);
#endif
    float gm = clamp(length(g) / gradientScale, 0.0, 1.0);
    vec2 uv = (vec2(v, gm) * vec2(float(TF_BINS - 1), float(TF_GRADIENT_BINS - 1)) + 0.5) /
              vec2(float(TF_BINS), float(TF_GRADIENT_BINS));
    vec4 tf = texture(tfLut, uv);
    float alpha = (1.0 - pow(1.0 - min(tf.a, 0.999), len)) * weight;
    if (alpha > 0.001) {
        composite(acc, shade(tf.rgb, g, rayWorld), alpha);
        return acc.a > 0.98;
    }
    return false;
}

ivec3 blockAt(vec3 p, ivec3 grid) {
    return clamp(ivec3(floor((p + 0.5) / skipBlock)), ivec3(0), grid - 1);
}

#if HAS_LABELS
// The box of the blocks holding a label (render::StructureLabels::blockBoxLo/Hi): rays that
// miss it search no further.
uniform ivec3 labelBlocksLo;
uniform ivec3 labelBlocksHi;

// What findLabel found: the structure (its label, 0: none), the first sample of the ray whose
// nearest voxel holds it (labelSampleT: the scan is marched up to there) and where the ray
// crosses its surface (labelT). Samples before labelFrom were checked already.
uint labelHit = 0u;
float labelSampleT = -1.0;
float labelT = -1.0;
float labelFrom = -1.0;

uint labelAt(vec3 p) {
    return texelFetch(labels, clamp(ivec3(floor(p + 0.5)), ivec3(0), volumeDims - 1), 0).r;
}

// A label among the corners of p's trilinear cell, 0 where none holds one.
uint labelOfCell(vec3 p) {
    ivec3 base = ivec3(floor(clamp(p, vec3(0.0), vec3(volumeDims - 1))));
    uint label = 0u;
    for (int c = 0; c < 8 && label == 0u; ++c) {
        ivec3 v = min(base + ivec3(c & 1, (c >> 1) & 1, c >> 2), volumeDims - 1);
        label = texelFetch(labels, v, 0).r;
    }
    return label;
}

// The trilinear blend of "the voxel holds `label`" at p, whose 0.5 level is drawn as the
// structure's outline: rounder than its voxels' faces. 8 fetches.
float labelOccupancy(vec3 p, uint label) {
    vec3 q = clamp(p, vec3(0.0), vec3(volumeDims - 1));
    ivec3 base = ivec3(floor(q));
    vec3 f = q - vec3(base);
    float occupancy = 0.0;
    for (int c = 0; c < 8; ++c) {
        ivec3 corner = ivec3(c & 1, (c >> 1) & 1, c >> 2);
        vec3 w = mix(1.0 - f, f, vec3(corner));
        ivec3 v = min(base + corner, volumeDims - 1);
        occupancy += texelFetch(labels, v, 0).r == label ? w.x * w.y * w.z : 0.0;
    }
    return occupancy;
}

// Whether the ray meets the surface of the structure searchLabel found at labelSampleT,
// within a voxel and a half from there (before tEnd): then labelT is its crossing, by bisection
// from the sample before. Where the ray only grazes a voxel's corner it does not, and the search
// goes on from labelFrom, past what was checked.
bool labelConfirmed(vec3 origin, vec3 dir, float tEnd) {
    int samples = int(ceil(1.5 / max(length(dir), 1e-6) / stepMm));
    float a = labelSampleT - stepMm;
    float fa = labelOccupancy(origin + a * dir, labelHit);
    for (int i = 0; i <= samples; ++i) {
        float b = labelSampleT + float(i) * stepMm;
        if (b >= tEnd) {
            break;
        }
        float fb = labelOccupancy(origin + b * dir, labelHit);
        if (fb >= 0.5) {
            // Already inside at the sample before (the ray starts in the structure, or a
            // concave corner): the sample itself.
            float lo = fa < 0.5 ? a : b;
            float hi = b;
            for (int n = 0; n < 6; ++n) {
                float m = 0.5 * (lo + hi);
                if (labelOccupancy(origin + m * dir, labelHit) >= 0.5) {
                    hi = m;
                } else {
                    lo = m;
                }
            }
            labelT = hi;
            return true;
        }
        a = b;
        fa = fb;
    }
    labelFrom = labelSampleT + float(samples + 1) * stepMm;
    return false;
}

// The cubic B-spline (a [1 4 1] / 6 smoothing per axis, as render/surface_smooth.glsl rounds
// a mask's level set) of "the voxel holds labelHit" at p, and its gradient: continuous in
// value, gradient and curvature, so a voxels' staircase is not shaded step by step. 64
// fetches.
float labelSmooth(vec3 p, out vec3 grad) {
    vec3 q = clamp(p, vec3(0.0), vec3(volumeDims - 1));
    ivec3 base = ivec3(floor(q));
    vec3 f = q - vec3(base);
    vec3 g = 1.0 - f;
    vec3 w[4];
    vec3 d[4];
    w[0] = g * g * g / 6.0;
    w[1] = (3.0 * f * f * f - 6.0 * f * f + 4.0) / 6.0;
    w[2] = (-3.0 * f * f * f + 3.0 * f * f + 3.0 * f + 1.0) / 6.0;
    w[3] = f * f * f / 6.0;
    d[0] = -0.5 * g * g;
    d[1] = 0.5 * (3.0 * f * f - 4.0 * f);
    d[2] = 0.5 * (-3.0 * f * f + 2.0 * f + 1.0);
    d[3] = 0.5 * f * f;
    float value = 0.0;
    grad = vec3(0.0);
    for (int n = 0; n < 64; ++n) {
        ivec3 o = ivec3(n & 3, (n >> 2) & 3, n >> 4);
        ivec3 v = clamp(base + o - 1, ivec3(0), volumeDims - 1);
        if (texelFetch(labels, v, 0).r == labelHit) {
            value += w[o.x].x * w[o.y].y * w[o.z].z;
            grad += vec3(d[o.x].x * w[o.y].y * w[o.z].z, w[o.x].x * d[o.y].y * w[o.z].z,
                         w[o.x].x * w[o.y].y * d[o.z].z);
        }
    }
    return value;
}

// The structure's surface near labelT (the trilinear crossing): two Newton steps along the ray
// to the B-spline's 0.5 level, kept within a voxel of it, shaded with the B-spline's gradient
// there. Once per ray; the outline stays the trilinear one.
vec3 labelColour(vec3 origin, vec3 dir, vec3 rayWorld) {
    float reach = 1.0 / max(length(dir), 1e-6); // millimetres along the ray per voxel
    float tHit = labelT;
    vec3 grad = vec3(0.0);
    // One call site in a loop (64 fetches of code each): evaluate, then step.
    for (int i = 0; i < 3; ++i) {
        float f = labelSmooth(origin + tHit * dir, grad) - 0.5;
        if (i == 2) {
            break;
        }
        float slope = dot(grad, dir);
        float newton = f / (abs(slope) > 1e-6 ? slope : 1e30);
        tHit = clamp(tHit - newton, labelT - reach, labelT + reach);
    }
    return shade(labelColours[int(labelHit) - 1], grad, rayWorld);
}

// The first sample from t (on the lattice), before tEnd, whose nearest voxel holds a label:
// labelHit and labelSampleT. A loop of its own, before the scan's march, rather than a test in
// the march's loop: a ray crosses far fewer blocks than it takes samples, and a software
// rasteriser pays for a test in the march's every sample (a third more CPU time on the sample
// with two structures). Blocks without a label (the skipping texture's green) are jumped as
// marchScan jumps empty ones.
bool searchLabel(vec3 origin, vec3 dir, float t, float tEnd) {
    ivec3 grid = textureSize(skipGrid, 0);
    for (int guard = 0; guard < 16384 && t < tEnd; ++guard) {
        vec3 p = origin + t * dir;
        ivec3 b = blockAt(p, grid);
        if (texelFetch(skipGrid, b, 0).g > 0.5) {
            uint label = labelAt(p);
            if (label != 0u) {
                labelHit = label;
                labelSampleT = t;
                return true;
            }
        } else {
            vec3 blockLo = vec3(b) * skipBlock - 0.5;
            vec2 bh = boxHits(origin, dir, blockLo, blockLo + skipBlock);
            t += max(0.0, ceil((bh.y - t) / stepMm) - 1.0) * stepMm;
        }
        t += stepMm;
    }
    return false;
}

// The nearest structure along the ray from t to tEnd, if any (labelFound): the first labelled
// sample whose structure's surface the ray meets (labelConfirmed). A grazed corner is passed
// and the search goes on.
void findLabel(vec3 origin, vec3 dir, float t, float tEnd) {
    // Only where the ray crosses the labelled blocks' box (samples of block b lie within
    // [b block - 0.5, (b + 1) block - 0.5)).
    vec2 box = boxHits(origin, dir, vec3(labelBlocksLo) * skipBlock - 0.5,
                       vec3(labelBlocksHi + 1) * skipBlock - 0.5);
    t += max(0.0, ceil((box.x - t) / stepMm)) * stepMm;
    tEnd = min(tEnd, box.y);
    for (int tries = 0; tries < 64 && t < tEnd; ++tries) {
        if (!searchLabel(origin, dir, t, tEnd) || labelConfirmed(origin, dir, tEnd)) {
            return;
        }
        t = labelFrom;
        labelHit = 0u;
    }
    labelHit = 0u;
}
#endif

// Whether findLabel found a structure.
bool labelFound() {
#if HAS_LABELS
    return labelHit != 0u;
#else
    return false;
#endif
}

// Where the scan's march ends: half a step short of the structure findLabel found (the samples
// before it, as before the level set's surface), else at `otherwise`.
float marchEnd(float otherwise) {
#if HAS_LABELS
    return labelFound() ? labelSampleT - 0.5 * stepMm : otherwise;
#else
    return otherwise;
#endif
}

// The length of ray the sample at t stands for. Samples stand for stepMm each from the ray's
// entry (`lead` before the first, the jitter); the last one, where the ray leaves the volume
// or the clip plane at tEnd, for what is left. The ray's opacity then follows its length
// through a uniform region exactly: a whole sample more or less on neighbouring rays is what
// draws rings (wood grain) where that length crosses a multiple of the step, and noise where
// the first sample is jittered. `exact` 0: every sample a whole step (the scan up to a
// surface, which decides where the ray ends).
float sampleLength(float t, float tEnd, float lead, float exact) {
    float last = step(tEnd, t + stepMm) * exact;
    return mix(stepMm, tEnd - t + lead, last);
}

// The scan alone from t to tEnd (exclusive), skipping blocks with nothing visible.
void marchScan(inout vec4 acc, vec3 origin, vec3 dir, vec3 rayWorld, float t, float tEnd,
               float lead, float exact) {
    // A ray stays in a block for many samples: its skipping verdict is looked up once.
    ivec3 grid = textureSize(skipGrid, 0);
    ivec3 block = ivec3(-1);
    bool blockUsed = false;
    for (int guard = 0; guard < 16384 && t < tEnd; ++guard) {
        vec3 p = origin + t * dir;
        ivec3 b = blockAt(p, grid);
        if (b != block) {
            block = b;
            blockUsed = blockOccupied(b);
        }
        if (blockUsed) {
            if (addScanSample(acc, p, sampleLength(t, tEnd, lead, exact), 1.0, rayWorld)) {
                return;
            }
        } else {
            // Nothing to see in this block: jump to where the ray leaves it, keeping samples on
            // the same lattice.
            vec3 blockLo = vec3(b) * skipBlock - 0.5;
            vec2 bh = boxHits(origin, dir, blockLo, blockLo + skipBlock);
            t += max(0.0, ceil((bh.y - t) / stepMm) - 1.0) * stepMm;
        }
        t += stepMm;
    }
}

#if HAS_SURFACE
#define DATA_SPEED_INTENSITY_UNIT VIEW_SURFACE_INTENSITY_UNIT
#define DATA_SPEED_FACTOR_UNIT VIEW_SURFACE_FACTOR_UNIT
#include "render/surface_smooth.glsl"

// Bricks not stored as constant outside lie in bounds[0..2] ..= bounds[3..5] (render/
// band_bounds.comp, run before each draw with a level set); max < min when there are none.
layout(std430, binding = VIEW_BAND_BOUNDS_BINDING) readonly buffer BandBounds { int bounds[6]; };

// The pixels whose ray hits an opaque surface, for the second pass (SURFACE_PASS): the
// refinement's hundreds of reads then run for them only, where within the first pass every
// pixel would run them (a software rasteriser runs a branch's code whether or not a pixel of
// its SIMD group takes it). Per hit: what was
// gathered in front of it as half floats (rg, ba), the pixel (x | y << 16) and the hit's t.
// hitGroups is the second pass's indirect dispatch. Reset to 0, 1, 1, 0 before each draw.
layout(std430, binding = VIEW_SURFACE_HITS_BINDING) buffer SurfaceHits {
    uint hitGroups[3];
    uint hitCount;
    uvec4 hits[];
};

// t of the first sample on the lattice from t whose phi has the other sign than the first
// sample's, or -1 when the ray leaves first. Every sample skipped below would have given the
// first sample's sign, so the picture is the one a walk of every sample draws:
// - beyond the box of bricks that are not constant outside (the positions whose trilinear cell
//   touches one of them), phi is +PHI_FAR: a ray that starts outside the surface searches only
//   where it crosses that box;
// - within it, most of a ray lies in bricks stored as constant inside/outside: where phiFast
//   gives the first sample's constant up to the brick's far side, those samples are jumped
//   (8 lookups per sample in the seams between bricks, one per brick elsewhere).
float firstCrossing(vec3 origin, vec3 dir, float t, float tEnd) {
    ivec3 bandLo = ivec3(bounds[0], bounds[1], bounds[2]);
    ivec3 bandHi = ivec3(bounds[3], bounds[4], bounds[5]);
    if (any(lessThan(bandHi, bandLo))) {
        return -1.0; // every brick outside: no surface
    }
    // A cell touches the box from one voxel before its first brick; the volume's faces clamp.
    vec3 boxLo = mix(vec3(bandLo * BRICK_SIZE) - 1.0, vec3(-2.0), equal(bandLo, ivec3(0)));
    vec3 boxHi = mix(vec3(bandHi * BRICK_SIZE + BRICK_SIZE), vec3(volumeDims) + 1.0,
                     equal(bandHi, brickGrid - 1));
    bool firstInside = phiFast(origin + t * dir) <= 0.0;
    if (!firstInside) {
        vec2 box = boxHits(origin, dir, boxLo, boxHi);
        if (box.x > box.y) {
            return -1.0;
        }
        // Outside the box until box.x and again after box.y: search from the first sample at
        // or after box.x, and no further than box.y.
        t += max(0.0, ceil((box.x - t) / stepMm)) * stepMm;
        tEnd = min(tEnd, box.y);
    }
    for (int guard = 0; guard < 16384 && t < tEnd; ++guard) {
        vec3 p = origin + t * dir;
        ivec3 brick;
        bool inside;
        if (!constantBrickAt(p, brick, inside)) {
            inside = phiTrilinear(p) <= 0.0;
        } else if (inside == firstInside) {
            // The positions where constantBrickAt gives this brick: 8b <= p < 8b + 7 per axis,
            // reaching past the volume's faces at the first and last bricks (clamped corners).
            vec3 lo = mix(vec3(brick * BRICK_SIZE), vec3(-1.0), equal(brick, ivec3(0)));
            vec3 hi = mix(vec3(brick * BRICK_SIZE + BRICK_SIZE - 1), vec3(volumeDims),
                          equal(brick, brickGrid - 1));
            float exit = boxHits(origin, dir, lo, hi).y;
            t += max(0.0, ceil((exit - t) / stepMm) - 1.0) * stepMm;
        }
        if (inside != firstInside) {
            return t;
        }
        t += stepMm;
    }
    return -1.0;
}

// The shaded surface where phi crosses zero between the samples at t - stepMm and t: the
// crossing of trilinear phi by bisection, then of the smooth reconstruction (phiSmooth, with
// the data term's crossing where phi is a step: render/surface_smooth.glsl) by Newton steps
// along the ray from there, shaded with its gradient. The Newton steps stay within a voxel of
// the trilinear crossing (the B-spline's zero lies within a voxel of it: it reproduces linear
// phi exactly, and where phi is a step the front stopped where D changes sign); a grazing ray
// keeps the trilinear crossing.
vec3 surfaceColour(vec3 origin, vec3 dir, vec3 rayWorld, float t) {
    float a = t - stepMm;
    float b = t;
    float fa = phiTrilinear(origin + a * dir);
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
    float tLinear = 0.5 * (a + b);
    float reach = 1.0 / max(length(dir), 1e-6); // millimetres along the ray per voxel
    float tHit = tLinear;
    bool fromData = dataPlacesSurface(origin + tLinear * dir);
    vec3 grad = vec3(0.0);
    // One call site in a loop (each call site is 64 pool reads of code): evaluate, then step;
    // three evaluations from the data term, and where they found no crossing of it near the
    // ray (a front held where D has none: a barrier, a reach), three more from phi.
    for (int i = 0; i < 6; ++i) {
        float f = phiSmooth(origin + tHit * dir, fromData, grad);
        float slope = dot(grad, dir); // dphi / dt
        float newton = f / (abs(slope) > 1e-6 ? slope : 1e30);
        if (i == 2 || i == 5) {
            if (!fromData || abs(newton) < 0.5 * reach) {
                break;
            }
            fromData = false;
            tHit = tLinear;
        } else {
            tHit = clamp(tHit - newton, tLinear - reach, tLinear + reach);
        }
    }
    return shade(SURFACE_COLOUR, grad, rayWorld);
}

// The scan and the surface together: a translucent surface, or the surface as region of
// interest. The march stops at each crossing, and the surface is refined and composited between
// the two loops, then the march goes on: inside the loop a software rasteriser would run the
// refinement's hundreds of reads in every sample, crossing or not.
void marchWithSurface(inout vec4 acc, vec3 origin, vec3 dir, vec3 rayWorld, float t, float tEnd,
                      float lead) {
    ivec3 grid = textureSize(skipGrid, 0);
    ivec3 block = ivec3(-1);
    bool blockUsed = false;
    float prevPhi = phiFast(origin + t * dir);
    int guard = 0;
    for (int crossings = 0; crossings < 16384; ++crossings) {
        float tCross = -1.0;
        for (; guard < 16384 && t < tEnd; ++guard) {
            vec3 p = origin + t * dir;
            float phi = phiFast(p);
            bool crossing = surfaceMode != 0 && (phi <= 0.0) != (prevPhi <= 0.0);
            prevPhi = phi;
            if (crossing) {
                // The surface before this sample's scan: the loop resumes at this sample, its
                // crossing already seen.
                tCross = t;
                break;
            }
            ivec3 b = blockAt(p, grid);
            if (b != block) {
                block = b;
                blockUsed = blockOccupied(b);
            }
            // Outside the surface the scan is hidden (inside only) or dimmed.
            float weight =
                phi > 0.0 ? (roiMode == 1 ? 0.0 : (roiMode == 2 ? dimFactor : 1.0)) : 1.0;
            if (blockUsed && weight > 0.0 &&
                addScanSample(acc, p, sampleLength(t, tEnd, lead, 1.0), weight, rayWorld)) {
                return;
            }
            t += stepMm;
        }
        if (tCross < 0.0) {
            return;
        }
        composite(acc, surfaceColour(origin, dir, rayWorld, tCross),
                  surfaceMode == 1 ? 1.0 : SURFACE_TRANSLUCENT_ALPHA);
        if (acc.a > 0.98) {
            return;
        }
    }
}
#endif

// The ray through the pixel's centre: its world direction, and its direction in voxel-index
// space (voxels per millimetre along the ray).
void pixelRay(ivec2 pixel, out vec3 rayWorld, out vec3 dir) {
    vec2 ndc = vec2((float(pixel.x) + 0.5) / float(outSize.x) * 2.0 - 1.0,
                    1.0 - (float(pixel.y) + 0.5) / float(outSize.y) * 2.0);
    rayWorld = normalize(camForward + ndc.x * camRight + ndc.y * camUp);
    dir = worldToIndex * rayWorld;
}

#if SURFACE_PASS
// The second pass: the opaque surface of the rays that hit it, refined and composited behind
// what the first pass gathered in front of it.
void main() {
    uint stride = gl_NumWorkGroups.x * uint(SURFACE_PASS_GROUP);
    for (uint n = gl_GlobalInvocationID.x; n < hitCount; n += stride) {
        uvec4 hit = hits[n];
        ivec2 pixel = ivec2(int(hit.z & 0xffffu), int(hit.z >> 16));
        vec4 acc = vec4(unpackHalf2x16(hit.x), unpackHalf2x16(hit.y));
        vec3 rayWorld;
        vec3 dir;
        pixelRay(pixel, rayWorld, dir);
        composite(acc, surfaceColour(eyeIndex, dir, rayWorld, uintBitsToFloat(hit.w)), 1.0);
        imageStore(outImage, pixel, vec4(acc.rgb, 1.0));
    }
}
#else
void main() {
    ivec2 pixel = ivec2(gl_GlobalInvocationID.xy) + firstPixel;
    if (pixel.x >= outSize.x || pixel.y >= outSize.y) {
        return;
    }
    vec3 rayWorld;
    vec3 dir;
    pixelRay(pixel, rayWorld, dir);
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
#if HAS_LABELS
            // Another structure's section, tinted in its colour over the scan: where the
            // occupancy of a label of p's cell reaches 0.5 (the outline the march draws).
            uint label = labelOfCell(p);
            if (label != 0u && labelOccupancy(p, label) >= 0.5) {
                colour = mix(colour, labelColours[int(label) - 1], 0.5);
            }
#endif
            if (hasSurface != 0 && abs(phiTrilinear(p)) < lineWidth) {
                colour = CONTOUR_YELLOW;
            }
            acc = vec4(colour, 1.0);
        } else {
            // A fixed per-pixel offset of the sample lattice (interleaved gradient noise) turns
            // wood-grain aliasing into fine noise, the same in every frame, so a still picture
            // does not shimmer.
            float ign = fract(dot(vec2(pixel), vec2(0.06711056, 0.00583715)));
            float lead = stepMm * fract(52.9829189 * ign);
            float t = span.x + lead;
#if HAS_SURFACE
            if (surfaceMode == 1 && roiMode == 0) {
                // An opaque surface and no region of interest: find the surface first, then
                // march the scan up to it without the level set's code in the loop.
                float tHit = firstCrossing(origin, dir, t, span.y);
                // Half a step short of the hit: the samples before it, however t was rounded.
                // One call for both (a software rasteriser runs both sides of a branch).
                bool hit = tHit >= 0.0;
#if HAS_LABELS
                // Another structure in front of the surface hides it.
                findLabel(origin, dir, t, hit ? tHit : span.y);
                hit = hit && !labelFound();
#endif
                marchScan(acc, origin, dir, rayWorld, t,
                          marchEnd(hit ? tHit - 0.5 * stepMm : span.y), lead,
                          hit || labelFound() ? 0.0 : 1.0);
                if (hit && acc.a <= 0.98) {
                    // The surface is refined and composited by the second pass, for these
                    // pixels only.
                    uint n = atomicAdd(hitCount, 1u);
                    hits[n] = uvec4(packHalf2x16(acc.rg), packHalf2x16(acc.ba),
                                    uint(pixel.x) | (uint(pixel.y) << 16), floatBitsToUint(tHit));
                    atomicMax(hitGroups[0],
                              min(n / uint(SURFACE_PASS_GROUP) + 1u, SURFACE_PASS_MAX_GROUPS));
                    return;
                }
            } else {
#if HAS_LABELS
                findLabel(origin, dir, t, span.y);
#endif
                marchWithSurface(acc, origin, dir, rayWorld, t, marchEnd(span.y), lead);
            }
#else
#if HAS_LABELS
            findLabel(origin, dir, t, span.y);
#endif
            marchScan(acc, origin, dir, rayWorld, t, marchEnd(span.y), lead,
                      labelFound() ? 0.0 : 1.0);
#endif
#if HAS_LABELS
            // Nearer than the level set's surface and not hidden by the scan: the marches
            // stopped in front of it.
            if (labelFound() && acc.a <= 0.98) {
                composite(acc, labelColour(origin, dir, rayWorld), 1.0);
            }
#endif
        }
    }
    imageStore(outImage, pixel, vec4(acc.rgb, 1.0));
}
#endif
