#include "speed/surface_shell.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace steerseg::speed {

namespace {

bool finite(float v) {
    return std::isfinite(v);
}

bool finite(const glm::vec3& v) {
    return finite(v.x) && finite(v.y) && finite(v.z);
}

bool inWindow(double value, float low, float high) {
    return value >= static_cast<double>(low) && value <= static_cast<double>(high);
}

bool within(const glm::ivec3& voxel, const glm::vec3& centre, float radius) {
    const glm::vec3 d = glm::vec3(voxel) - centre;
    return glm::dot(d, d) <= radius * radius;
}

// As the speed sees the voxel (shaders/solver/barrier_speed.glsl): the global window, or a
// local one within its reach.
bool admitted(const glm::ivec3& voxel, double value, const ShellParams& params) {
    if (inWindow(value, params.low, params.high)) {
        return true;
    }
    return std::any_of(params.local.begin(), params.local.end(), [&](const LocalWindow& w) {
        return within(voxel, w.centre, w.reach) && inWindow(value, w.low, w.high);
    });
}

void check(std::span<const float> phi, const Volume& scan, const ShellParams& params) {
    if (phi.size() != scan.geometry().voxelCount()) {
        throw std::invalid_argument("surface shell: the level set and the scan differ in size");
    }
    if (!finite(params.nearVoxels) || !finite(params.farVoxels) ||
        !(params.nearVoxels < params.farVoxels) || !finite(params.low) || !finite(params.high) ||
        !(params.low <= params.high) || !finite(params.radius) || !(params.radius > 0.0F)) {
        throw std::invalid_argument("surface shell: its distances, window or radius are not "
                                    "finite and ordered");
    }
    for (const LocalWindow& w : params.local) {
        if (!finite(w.centre) || !finite(w.reach) || w.reach < 0.0F || !finite(w.low) ||
            !finite(w.high) || !(w.low <= w.high)) {
            throw std::invalid_argument("surface shell: a local window is not a finite position, "
                                        "reach and ordered window");
        }
    }
}

// Evenly spaced in raster order, they reach every slice of the shell, and the same surface
// gives the same examples (a resumed session retrains the same forest).
std::vector<model::Sphere> spread(const std::vector<glm::ivec3>& candidates,
                                  const ShellParams& params) {
    const std::size_t n = candidates.size();
    const std::size_t take = std::min(n, params.most);
    std::vector<model::Sphere> spheres;
    spheres.reserve(take);
    for (std::size_t c = 0; c < take; ++c) {
        spheres.push_back({glm::vec3(candidates[(2 * c + 1) * n / (2 * take)]), params.radius});
    }
    return spheres;
}

} // namespace

std::vector<model::Sphere> outsideShell(std::span<const float> phi, const Volume& scan,
                                        const ShellParams& params) {
    check(phi, scan, params);
    const glm::ivec3 dims = scan.dims();
    std::vector<glm::ivec3> candidates;
    std::size_t v = 0;
    for (int k = 0; k < dims.z; ++k) {
        for (int j = 0; j < dims.y; ++j) {
            for (int i = 0; i < dims.x; ++i, ++v) {
                if (!(phi[v] > params.nearVoxels && phi[v] <= params.farVoxels)) {
                    continue;
                }
                const glm::ivec3 voxel(i, j, k);
                if (!admitted(voxel, scan.rescale().apply(scan.storedAt(v)), params)) {
                    candidates.push_back(voxel);
                }
            }
        }
    }
    return spread(candidates, params);
}

} // namespace steerseg::speed
