// The data term of the speed, D(I) = eps - |I - T| (Lefohn et al. 2003): positive (grow) where
// the intensity lies within T +/- eps. CPU twin: thresholdSpeed() in app/solver/phi_stencil.hpp.
// Another speed function replaces this file, keeping dataSpeed(voxel)'s meaning: the outward
// speed in voxels per unit time before the alpha weighting.
#include "common/bindings.h"
precision highp sampler3D;
layout(binding = SOLVER_SCAN_UNIT) uniform highp sampler3D scan; // real-unit intensities (R32F)
uniform float targetT;
uniform float halfWidth;

float dataSpeed(ivec3 voxel) {
    return halfWidth - abs(texelFetch(scan, voxel, 0).r - targetT);
}
