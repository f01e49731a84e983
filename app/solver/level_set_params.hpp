#pragma once

#include <glm/glm.hpp>
#include <string>

namespace steerseg {

// The segmentation speed's parameters (Lefohn et al. 2003):
//   F = alpha * (eps - |I - T|) - (1 - alpha) * H,   H = div(grad phi / |grad phi|)
// The surface moves along its outward normal at speed F (phi < 0 inside), so the data term
// grows the region where I is within T +/- eps and the curvature term smooths it. T and eps are
// in the scan's real units (HU for CT), everything else in voxel units (unit spacing).
struct LevelSetParams {
    float T = 0.0F;
    float eps = 0.0F;
    float alpha = 1.0F;
};

// |phi| is clamped to this many voxels; bricks whose voxels are all at +-kPhiFar hold no storage.
inline constexpr float kPhiFar = 4.0F;

// Weight of the rescaling term G = w * phi * (1 - |grad phi|), which keeps phi close to a clamped
// distance without moving the zero level set. Its speed (w * kPhiFar) enters the time step.
inline constexpr float kRescaleWeight = 0.25F;

// Throws std::invalid_argument with a one-line message for non-finite values, eps < 0 or alpha
// outside [0, 1]. Used by the GPU solver, the reference solver and the command line.
void validateParams(const LevelSetParams& params);

// Explicit-Euler stability, shared by both solvers (the GPU evaluates the same expression with
// these constants as uniforms):
//   dt = 1 / (max over the front (onFront, phi_stencil.hpp) of |alpha * D| / courant + fixedRate)
// fixedRate = (1 - alpha) * 6 (central-difference curvature term, 1 / (2 * 3) at unit spacing)
// + the rescaling term's speed. courant is 0.5, not 0.9: the 3D up-wind scheme is stable for
// dt * |F| * (|nx| + |ny| + |nz|) <= 1, up to sqrt(3) * dt * |F| on a diagonal front; with 0.9
// a growing sphere ran ahead along the diagonals (measured on the reference solver).
struct TimeStepRule {
    float courant = 0.5F;
    float fixedRate = 0.0F;
};
TimeStepRule timeStepRule(const LevelSetParams& params);
float stableTimeStep(const TimeStepRule& rule, float maxDataRate);

// A sphere edit in voxel-index coordinates (i, j, k in storage order; radius in voxels).
struct Sphere {
    glm::vec3 centre{0.0F};
    float radius = 0.0F;
};

// Throws std::invalid_argument unless the radius is positive, finite and at most the volume's
// diagonal (dims, in voxels) and the centre lies inside the volume. Every sphere edit (the GPU
// and reference solvers' addSphere/removeSphere, the command line's --seed/--erase) goes through
// it: a larger radius adds nothing but overflows the edit's voxel bounds.
void validateSphere(const Sphere& sphere, const glm::ivec3& dims);

// Signed distance from voxel centre `voxel` to the sphere's surface (negative inside).
inline float sphereDistance(const Sphere& s, const glm::vec3& voxel) {
    return glm::length(voxel - s.centre) - s.radius;
}

std::string describe(const LevelSetParams& params);

} // namespace steerseg
