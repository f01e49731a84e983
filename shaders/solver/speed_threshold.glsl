// The data term of the speed, the outward speed in voxels per unit time before the alpha
// weighting (docs/speed.md), by speedKind (speed::SpeedKind's order):
//   0 threshold  eps - |I - T|          (Lefohn et al. 2003): positive where I lies in T +/- eps
//   1 edge       g * (eps - |I - T|)    g the edge-stopping factor (speed/edge_factor.comp)
//   2 classify   P(inside) - P(outside) the classifier's output, in [-1, 1]
// I is the scan or its smoothed copy, whichever the host binds. CPU twin: dataSpeed() in
// app/solver/phi_stencil.hpp.
#include "common/bindings.h"
precision highp sampler3D;
layout(binding = SOLVER_SCAN_UNIT) uniform highp sampler3D scan; // real-unit intensities (R32F)
layout(binding = SOLVER_FACTOR_UNIT) uniform highp sampler3D speedFactor; // R32F, kinds 1 and 2
uniform float targetT;
uniform float halfWidth;
uniform int speedKind;

float dataSpeed(ivec3 voxel) {
    if (speedKind == 2) {
        return texelFetch(speedFactor, voxel, 0).r;
    }
    float d = halfWidth - abs(texelFetch(scan, voxel, 0).r - targetT);
    if (speedKind == 1) {
        d *= texelFetch(speedFactor, voxel, 0).r;
    }
    return d;
}
