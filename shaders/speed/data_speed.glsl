// The data term of the speed, the outward speed in voxels per unit time before the alpha
// weighting (docs/speed.md), by speedKind (model::SpeedKind's order):
//   0 threshold  eps - |I - T|          (Lefohn et al. 2003): positive where I lies in T +/- eps
//   1 edge       g * (eps - |I - T|)    g the edge-stopping factor (speed/edge_factor.comp)
//   2 classify   P(inside) - P(outside) the classifier's output c, in [-1, 1]; within the window
//                (classifyWithinWindow, the console's), min(c, w) for the window's speed
//                w = (eps - |I - T|) / eps clamped to [-1, 1]: inside where the forest and the
//                window both say so, so the forest takes away what the window admits and adds
//                nothing it refuses (docs/speed.md "Classify within the window")
// I is the scan or its smoothed copy, whichever the host binds (speed::bindSpeedTextures). The
// includer names the texture units (DATA_SPEED_INTENSITY_UNIT, DATA_SPEED_FACTOR_UNIT), so a
// view of the speed can read the same definition beside its own samplers. CPU twin: dataSpeed()
// in app/solver/phi_stencil.hpp.
#if !defined(DATA_SPEED_INTENSITY_UNIT) || !defined(DATA_SPEED_FACTOR_UNIT)
#error "define DATA_SPEED_INTENSITY_UNIT and DATA_SPEED_FACTOR_UNIT before speed/data_speed.glsl"
#endif
precision highp sampler3D;
// Real-unit intensities (R32F), texelFetch only.
layout(binding = DATA_SPEED_INTENSITY_UNIT) uniform highp sampler3D speedIntensity;
// R32F, read by kinds 1 and 2 only.
layout(binding = DATA_SPEED_FACTOR_UNIT) uniform highp sampler3D speedFactor;
uniform float T;
uniform float eps;
uniform int speedKind;
uniform int classifyWithinWindow; // kind 2 only: non-zero to bound it by the window at T

// Kinds 0 and 1 for any window: the one a correction's tissue level opens around it
// (solver/barrier_speed.glsl) is the same term as the one at T (centre T, half-width eps).
float windowSpeed(ivec3 voxel, float centre, float halfWidth) {
    float d = halfWidth - abs(texelFetch(speedIntensity, voxel, 0).r - centre);
    if (speedKind == 1) {
        d *= texelFetch(speedFactor, voxel, 0).r;
    }
    return d;
}

// The classify speed c within a window of speed d and half-width h (eps may be 0: the window
// then admits T alone, and d / h stays finite or infinite, never NaN). Rises with d / h, so the
// widest of several windows (a correction's tissue window, barrier_speed.glsl) gives the largest
// value. CPU twin: classifyWithin() in app/solver/phi_stencil.hpp.
float classifyWithin(float c, float d, float h) {
    return min(clamp(d / max(h, 1e-20), -1.0, 1.0), c);
}

float dataSpeed(ivec3 voxel) {
    if (speedKind == 2) {
        float c = texelFetch(speedFactor, voxel, 0).r;
        return classifyWithinWindow != 0 ? classifyWithin(c, windowSpeed(voxel, T, eps), eps) : c;
    }
    return windowSpeed(voxel, T, eps);
}
