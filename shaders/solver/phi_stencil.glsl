// One explicit level-set step at one voxel: the same arithmetic as app/solver/phi_stencil.hpp
// (the reference solver's); keep the two in step. Unit voxel spacing.
#ifndef RESCALE_WEIGHT
#define RESCALE_WEIGHT 0.25
#endif

struct PhiStencil {
    float c;
    float xm, xp, ym, yp, zm, zp;
    float xpyp, xpym, xmyp, xmym;
    float xpzp, xpzm, xmzp, xmzm;
    float ypzp, ypzm, ymzp, ymzm;
};

float upwindGradient(PhiStencil s, float direction) {
    vec3 dm = vec3(s.c - s.xm, s.c - s.ym, s.c - s.zm);
    vec3 dp = vec3(s.xp - s.c, s.yp - s.c, s.zp - s.c);
    vec3 back = direction > 0.0 ? max(dm, vec3(0.0)) : min(dm, vec3(0.0));
    vec3 ahead = direction > 0.0 ? min(dp, vec3(0.0)) : max(dp, vec3(0.0));
    return sqrt(dot(back, back) + dot(ahead, ahead));
}

// H * |grad phi| by the direct mean-curvature formula from central first and second
// differences (not the paper's difference of normals); see app/solver/phi_stencil.hpp.
float curvatureTimesGradient(PhiStencil s) {
    float x = 0.5 * (s.xp - s.xm);
    float y = 0.5 * (s.yp - s.ym);
    float z = 0.5 * (s.zp - s.zm);
    float g2 = x * x + y * y + z * z;
    if (g2 < 1e-12) {
        return 0.0;
    }
    float xx = s.xp - 2.0 * s.c + s.xm;
    float yy = s.yp - 2.0 * s.c + s.ym;
    float zz = s.zp - 2.0 * s.c + s.zm;
    float xy = 0.25 * (s.xpyp - s.xpym - s.xmyp + s.xmym);
    float xz = 0.25 * (s.xpzp - s.xpzm - s.xmzp + s.xmzm);
    float yz = 0.25 * (s.ypzp - s.ypzm - s.ymzp + s.ymzm);
    float num = (yy + zz) * x * x + (xx + zz) * y * y + (xx + yy) * z * z -
                2.0 * (x * y * xy + x * z * xz + y * z * yz);
    return num / g2;
}

// The narrow band: the centre or a face neighbour is not clamped (only the face values are read).
bool inNarrowBand(PhiStencil s) {
    float m = min(min(min(abs(s.c), abs(s.xm)), min(abs(s.xp), abs(s.ym))),
                  min(min(abs(s.yp), abs(s.zm)), abs(s.zp)));
    return m < PHI_FAR;
}

// On the front: the voxel and a face neighbour lie on different sides of the surface. Only
// front voxels set the time step (see app/solver/phi_stencil.hpp).
bool onFront(PhiStencil s) {
    bool inside = s.c < 0.0;
    return (s.xm < 0.0) != inside || (s.xp < 0.0) != inside || (s.ym < 0.0) != inside ||
           (s.yp < 0.0) != inside || (s.zm < 0.0) != inside || (s.zp < 0.0) != inside;
}

// phi after one step of dt; the data term is limited to the range of the voxel and its face
// neighbours (why: app/solver/phi_stencil.hpp).
float phiStep(PhiStencil s, float dataSpeed, float alpha, float dt) {
    float f = alpha * dataSpeed;
    float lo = min(min(min(s.c, s.xm), min(s.xp, s.ym)), min(min(s.yp, s.zm), s.zp));
    float hi = max(max(max(s.c, s.xm), max(s.xp, s.ym)), max(max(s.yp, s.zm), s.zp));
    float moved = clamp(s.c - dt * f * upwindGradient(s, f), lo, hi);
    float curvature = (1.0 - alpha) * curvatureTimesGradient(s);
    float rescale = RESCALE_WEIGHT * s.c * (1.0 - upwindGradient(s, s.c >= 0.0 ? 1.0 : -1.0));
    return clamp(moved + dt * (curvature + rescale), -PHI_FAR, PHI_FAR);
}
