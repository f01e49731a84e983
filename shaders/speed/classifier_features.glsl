// The classifier's per-voxel features (speed/classifier_layout.h), one code for the training
// samples (classifier_gather.comp) and for every voxel (classifier_evaluate.comp), so that the
// forest meets at evaluation exactly the numbers it was trained on. Computed on the fly from the
// intensities: a stored feature stack would be 32 bytes per voxel (4 GiB at 512^3). Steps of
// classifierStride voxels along each axis (speed::classifierFeatureStride: about a millimetre,
// so a fine series' windows cover the tissue a coarse one's do); outside the scan the nearest
// edge voxel stands in (clamp to edge). Sums are of differences
// from the centre voxel, so that a variance of a few units survives intensities in the
// thousands in single precision.
#include "common/bindings.h"
#include "speed/classifier_layout.h"

layout(binding = SPEED_SOURCE_UNIT) uniform highp sampler3D classifierIntensity;
uniform ivec3 classifierDims;
uniform ivec3 classifierStride; // >= 1 on each axis

#if CLASSIFIER_FEATURE_COUNT != 8
#error "ClassifierFeatureVector holds eight features"
#endif

// Two vectors, not an array, and a feature picked by selects: no index into an array or a
// vector, which some drivers' compilers have handled wrongly. (On NVIDIA's driver 580 the
// features were right either way; the walk's node copy was what went wrong:
// speed/classifier_forest.glsl.)
struct ClassifierFeatureVector {
    vec4 lo; // features 0-3
    vec4 hi; // features 4-7
};

// Feature i (0..7) of fv, by selects rather than an index into a vector or an array.
float classifierFeature(ClassifierFeatureVector fv, int i) {
    vec4 q = i < 4 ? fv.lo : fv.hi;
    int c = i & 3;
    return c == 0 ? q.x : (c == 1 ? q.y : (c == 2 ? q.z : q.w));
}

float classifierFetch(ivec3 v) {
    return texelFetch(classifierIntensity, clamp(v, ivec3(0), classifierDims - 1), 0).r;
}

ClassifierFeatureVector classifierFeatures(ivec3 v) {
    float centre = classifierFetch(v);
    float s3 = 0.0;
    float q3 = 0.0;
    float s5 = 0.0;
    float q5 = 0.0;
    // m3(v + e) - m3(v - e) keeps only the 3x3 planes 1 and 2 voxels either side along e.
    vec3 g = vec3(0.0);
    for (int dz = -2; dz <= 2; ++dz) {
        for (int dy = -2; dy <= 2; ++dy) {
            for (int dx = -2; dx <= 2; ++dx) {
                ivec3 o = ivec3(dx, dy, dz);
                ivec3 a = abs(o);
                float d = classifierFetch(v + o * classifierStride) - centre;
                s5 += d;
                q5 += d * d;
                if (all(lessThanEqual(a, ivec3(1)))) {
                    s3 += d;
                    q3 += d * d;
                }
                if (a.y <= 1 && a.z <= 1) {
                    g.x += float(sign(dx)) * d;
                }
                if (a.x <= 1 && a.z <= 1) {
                    g.y += float(sign(dy)) * d;
                }
                if (a.x <= 1 && a.y <= 1) {
                    g.z += float(sign(dz)) * d;
                }
            }
        }
    }
    // The larger scale every second voxel: 125 fetches instead of 729.
    float s9 = 0.0;
    float q9 = 0.0;
    for (int dz = -4; dz <= 4; dz += 2) {
        for (int dy = -4; dy <= 4; dy += 2) {
            for (int dx = -4; dx <= 4; dx += 2) {
                float d = classifierFetch(v + ivec3(dx, dy, dz) * classifierStride) - centre;
                s9 += d;
                q9 += d * d;
            }
        }
    }
    float m3 = s3 / 27.0;
    float m5 = s5 / 125.0;
    float m9 = s9 / 125.0;
    ClassifierFeatureVector fv;
    fv.lo = vec4(centre, centre + m3, centre + m5, centre + m9);
    fv.hi = vec4(sqrt(max(q3 / 27.0 - m3 * m3, 0.0)), sqrt(max(q5 / 125.0 - m5 * m5, 0.0)),
                 sqrt(max(q9 / 125.0 - m9 * m9, 0.0)), length(g) * (0.5 / 27.0));
    return fv;
}
