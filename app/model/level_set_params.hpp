#pragma once

#include <cstddef>
#include <glm/glm.hpp>
#include <optional>
#include <string>

namespace steerseg::model {

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
//   dt = 1 / ((max|alpha * D| + kRescaleWeight * kPhiFar) / courant + (1 - alpha) * 6)
// with the maximum over the front (onFront, phi_stencil.hpp); fixedRate holds the last two
// terms. The step obeys, each term alone and together (the rates add):
// - Courant on the up-wind terms, the data speed |alpha D| and the rescaling term's speed
//   kRescaleWeight * |phi| <= kRescaleWeight * kPhiFar: dt * speed <= courant = 0.5. The 3D
//   up-wind scheme needs dt * speed * (|nx| + |ny| + |nz|) <= 1, up to sqrt(3) * dt * speed on a
//   diagonal front; with 0.9 a growing sphere ran ahead along the diagonals, and with the
//   rescaling term outside the factor (dt -> 1 at alpha = 1) phi oscillated where the seed's
//   distance has a kink (SolverTimeStepTest).
// - the explicit-diffusion limit of the curvature term, (1 - alpha) times a diffusion across the
//   normal: dt <= h^2 / (2 * dim * (1 - alpha)) = 1 / (6 * (1 - alpha)) at unit spacing h; at
//   1 / (3 * (1 - alpha)) the cube of SolverTimeStepTest blows up.
struct TimeStepRule {
    float courant = 0.5F;
    float fixedRate = 0.0F;
};
TimeStepRule timeStepRule(const LevelSetParams& params);
float stableTimeStep(const TimeStepRule& rule, float maxDataRate);

// A sphere edit in voxel-index coordinates (i, j, k in storage order). Its radius counts voxels
// along the scan's finest axis, and the sphere is round in millimetres: on a scan with 3 mm
// slices and 1 mm pixels a radius of 6 spans 6 pixels and 2 slices (sphereScale). The operator
// sizes a brush by what a slice shows; a ball in voxel steps would reach three times as far
// through the slices as it does across them.
struct Sphere {
    glm::vec3 centre{0.0F};
    float radius = 0.0F;
    bool operator==(const Sphere&) const = default;
};

// Where a run may move the surface (workflow::Engine::setReach): within the sphere both ways;
// outside it phi stays, or with `recedeOutside` it may only rise, so that the surface there
// withdraws but never advances (an erase's run that grew too far: docs/steering.md).
struct Reach {
    Sphere sphere;
    bool recedeOutside = false;
    bool operator==(const Reach&) const = default;
};

// How far an erase's run may take the surface back away from the erase (workflow::Engine::
// limitWithdrawal, docs/steering.md): beyond `around` it withdraws at most `depthMm` from where
// it stood when the limit was set; the surface's voxels deeper than that stay inside.
struct WithdrawLimit {
    Sphere around;
    double depthMm = 0.0;
    bool operator==(const WithdrawLimit&) const = default;
};

// Throws std::invalid_argument unless the radius is positive, finite and at most the volume's
// diagonal (dims, in voxels) and the centre lies inside the volume. Every sphere edit (the GPU
// and reference solvers' addSphere/removeSphere, the command line's --seed/--erase) goes through
// it: a larger radius adds nothing but overflows the edit's voxel bounds.
void validateSphere(const Sphere& sphere, const glm::ivec3& dims);

// A voxel step's length along each axis in units of the finest spacing (at least 1 each): what
// a sphere's radius is measured in (Sphere). (1, 1, 1) for an isotropic scan or spacing that is
// not finite and positive.
glm::vec3 sphereScale(const glm::dvec3& spacing);

// The sphere's distance from its centre, in its radius's units.
inline float sphereNorm(const glm::vec3& offset, const glm::vec3& scale) {
    return glm::length(offset * scale);
}

// Signed distance from voxel centre `voxel` to the sphere's surface (negative inside), in voxel
// steps to first order: the level set's units. The twin of shaders/solver/sphere_metric.glsl.
float sphereDistance(const Sphere& s, const glm::vec3& voxel,
                     const glm::vec3& scale = glm::vec3(1.0F));

// Half the sphere's extent along each axis, in voxels.
inline glm::vec3 sphereHalfExtent(const Sphere& s, const glm::vec3& scale) {
    return s.radius / scale;
}

// Whether voxel centre `voxel` lies in the sphere (on its surface included), in double.
inline bool sphereHolds(const Sphere& s, const glm::dvec3& voxel, const glm::vec3& scale) {
    const glm::dvec3 d = (voxel - glm::dvec3(s.centre)) * glm::dvec3(scale);
    return glm::dot(d, d) <= static_cast<double>(s.radius) * static_cast<double>(s.radius);
}

// The box of voxels a sphere may hold, clipped to a grid of `dims` (inclusive; empty where
// hi < lo): what a CPU loop over a sphere's voxels visits before asking sphereHolds.
struct VoxelBox {
    glm::ivec3 lo{0};
    glm::ivec3 hi{-1};
};
VoxelBox sphereVoxelBox(const Sphere& s, const glm::vec3& scale, const glm::ivec3& dims);

std::string describe(const LevelSetParams& params);

// A sphere whose side of the surface the operator fixed for the rest of the run
// (shaders/solver/barrier_speed.glsl): the front never enters a blocking one (an erase that
// sticks, a leak's neck) and never leaves a keeping one (an added correction in tissue the
// speed calls outside, which would otherwise recede the moment the front runs again).
//
// A keeping sphere of a later correction also carries the level of the tissue it was put on,
// for the threshold and edge speeds: within `reach` voxels of its centre, the window spans
// from T to `level`, eps beyond each, where it is T +- eps everywhere else (docs/steering.md).
// The operator added the sphere where the window at T missed the structure; the level teaches
// the window that tissue there, and only there, since a wider global window leaks.
struct TissueLevel {
    float level = 0.0F; // the scan's real units: the mean under the sphere
    float reach = 0.0F; // voxels from the sphere's centre
    bool operator==(const TissueLevel&) const = default;
};

struct Barrier {
    Sphere sphere;
    bool keep = false;
    std::optional<TissueLevel> tissue = std::nullopt; // keeping spheres only
    bool operator==(const Barrier&) const = default;
};

// validateSphere, and a tissue level only on a keeping sphere, finite, with a reach in (0, the
// volume's diagonal]; std::invalid_argument otherwise.
void validateBarrier(const Barrier& barrier, const glm::ivec3& dims);

// Barrier spheres one run may hold, of both kinds together (the shader's uniform array).
inline constexpr std::size_t kMaxBarriers = 16;

} // namespace steerseg::model
