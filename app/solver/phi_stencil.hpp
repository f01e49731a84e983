#pragma once

// The discretisation of one explicit level-set step at one voxel, on the CPU. The GPU's
// shaders/solver/phi_stencil.glsl is the same arithmetic line for line: keep them in step.
// Unit voxel spacing; neighbours outside the volume repeat the border voxel.

#include "model/level_set_params.hpp"
#include "model/speed_kind.hpp"

#include <algorithm>
#include <cmath>

namespace steerseg::solver {

// phi at the centre, its 6 face neighbours and 12 edge neighbours: what the up-wind gradient
// and the central first and second differences of the curvature term read (the mixed second
// differences need the edge neighbours, no stencil needs a corner). Names: p = +1, m = -1 along
// the axis.
struct PhiStencil {
    float c = 0.0F;
    float xm = 0.0F, xp = 0.0F, ym = 0.0F, yp = 0.0F, zm = 0.0F, zp = 0.0F;
    float xpyp = 0.0F, xpym = 0.0F, xmyp = 0.0F, xmym = 0.0F;
    float xpzp = 0.0F, xpzm = 0.0F, xmzp = 0.0F, xmzm = 0.0F;
    float ypzp = 0.0F, ypzm = 0.0F, ymzp = 0.0F, ymzm = 0.0F;
};

// Osher-Sethian up-wind |grad phi| for a front moving outward (direction > 0) or inward.
inline float upwindGradient(const PhiStencil& s, float direction) {
    const float dm[3] = {s.c - s.xm, s.c - s.ym, s.c - s.zm};
    const float dp[3] = {s.xp - s.c, s.yp - s.c, s.zp - s.c};
    float sum = 0.0F;
    for (int a = 0; a < 3; ++a) {
        const float back = direction > 0.0F ? std::max(dm[a], 0.0F) : std::min(dm[a], 0.0F);
        const float ahead = direction > 0.0F ? std::min(dp[a], 0.0F) : std::max(dp[a], 0.0F);
        sum += back * back + ahead * ahead;
    }
    return std::sqrt(sum);
}

// H * |grad phi| (H = div(grad phi / |grad phi|), the sum of the principal curvatures) by the
// direct mean-curvature formula
//   ((phi_yy + phi_zz) phi_x^2 + (phi_xx + phi_zz) phi_y^2 + (phi_xx + phi_yy) phi_z^2
//    - 2 (phi_x phi_y phi_xy + phi_x phi_z phi_xz + phi_y phi_z phi_yz)) / |grad phi|^2
// from central first and second differences at the voxel (as ITK's ComputeMeanCurvature), not
// the paper's difference of normals taken at the half-voxel faces; 0 where the central gradient
// vanishes (far from the surface, or at a saddle of phi).
inline float curvatureTimesGradient(const PhiStencil& s) {
    const float x = 0.5F * (s.xp - s.xm);
    const float y = 0.5F * (s.yp - s.ym);
    const float z = 0.5F * (s.zp - s.zm);
    const float g2 = x * x + y * y + z * z;
    if (g2 < 1e-12F) {
        return 0.0F;
    }
    const float xx = s.xp - 2.0F * s.c + s.xm;
    const float yy = s.yp - 2.0F * s.c + s.ym;
    const float zz = s.zp - 2.0F * s.c + s.zm;
    const float xy = 0.25F * (s.xpyp - s.xpym - s.xmyp + s.xmym);
    const float xz = 0.25F * (s.xpzp - s.xpzm - s.xmzp + s.xmzm);
    const float yz = 0.25F * (s.ypzp - s.ypzm - s.ymzp + s.ymzm);
    const float num = (yy + zz) * x * x + (xx + zz) * y * y + (xx + yy) * z * z -
                      2.0F * (x * y * xy + x * z * xz + y * z * yz);
    return num / g2;
}

// The narrow band: voxels whose phi can change (the centre or a face neighbour is not clamped).
inline bool inNarrowBand(const PhiStencil& s) {
    const float m = std::min({std::abs(s.c), std::abs(s.xm), std::abs(s.xp), std::abs(s.ym),
                              std::abs(s.yp), std::abs(s.zm), std::abs(s.zp)});
    return m < model::kPhiFar;
}

inline float clampPhi(float phi) {
    return std::clamp(phi, -model::kPhiFar, model::kPhiFar);
}

// On the front: the voxel and a face neighbour lie on different sides of the surface (phi < 0
// inside). Only front voxels set the time step, as only ITK's active layer does: elsewhere in
// the band |D| can be far larger (bone next to soft tissue) without the surface being near.
inline bool onFront(const PhiStencil& s) {
    const bool in = s.c < 0.0F;
    return (s.xm < 0.0F) != in || (s.xp < 0.0F) != in || (s.ym < 0.0F) != in ||
           (s.yp < 0.0F) != in || (s.zm < 0.0F) != in || (s.zp < 0.0F) != in;
}

// One explicit step at one voxel: phi + dt * d(phi)/dt, clamped to +-kPhiFar, for data speed
// D = eps - |I - T| (from the speed function).
// The data term's result is limited to the range of the voxel and its face neighbours. Under
// the front's time step an up-wind update lies in that range anyway (it is a convex
// combination of them); off the front the step may be too long for the local |D|, and the
// limit keeps such voxels from overshooting, in particular from changing side before the front
// reaches them.
inline float phiStep(const PhiStencil& s, float dataSpeed, float alpha, float dt) {
    const float f = alpha * dataSpeed;
    const float lo = std::min({s.c, s.xm, s.xp, s.ym, s.yp, s.zm, s.zp});
    const float hi = std::max({s.c, s.xm, s.xp, s.ym, s.yp, s.zm, s.zp});
    const float moved = std::clamp(s.c - dt * f * upwindGradient(s, f), lo, hi);
    const float curvature = (1.0F - alpha) * curvatureTimesGradient(s);
    // Rescaling: Godunov |grad phi| taken from the surface's side (information flows outward).
    const float rescale =
        model::kRescaleWeight * s.c * (1.0F - upwindGradient(s, s.c >= 0.0F ? 1.0F : -1.0F));
    return clampPhi(moved + dt * (curvature + rescale));
}

// The paper's threshold speed D(I) = eps - |I - T|. The GPU twin is
// shaders/speed/data_speed.glsl.
inline float thresholdSpeed(float intensity, const model::LevelSetParams& p) {
    return p.eps - std::abs(intensity - p.T);
}

// The classify speed c bounded by a window of speed d and half-width h: inside where both say
// so, so the forest takes away what the window admits and adds nothing it refuses (docs/speed.md
// "Classify within the window"). h may be 0 (eps = 0): the quotient stays finite or infinite,
// never NaN. The GPU twin is classifyWithin() in shaders/speed/data_speed.glsl.
inline float classifyWithin(float c, float d, float h) {
    return std::min(std::clamp(d / std::max(h, 1e-20F), -1.0F, 1.0F), c);
}

// The data term of each speed (docs/speed.md) from the voxel's intensity and its precomputed
// factor (edge: g; classify: P(in) - P(out), within T +- eps when withinWindow). The GPU twin is
// dataSpeed() in shaders/speed/data_speed.glsl.
inline float dataSpeed(float intensity, float factor, model::SpeedKind kind,
                       const model::LevelSetParams& p, bool withinWindow = false) {
    switch (kind) {
    case model::SpeedKind::Classify:
        return withinWindow ? classifyWithin(factor, thresholdSpeed(intensity, p), p.eps) : factor;
    case model::SpeedKind::Edge:
        return factor * thresholdSpeed(intensity, p);
    case model::SpeedKind::Threshold:
        break;
    }
    return thresholdSpeed(intensity, p);
}

} // namespace steerseg::solver
