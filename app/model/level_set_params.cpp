#include "model/level_set_params.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>

namespace steerseg::model {

void validateParams(const LevelSetParams& p) {
    if (!std::isfinite(p.T) || !std::isfinite(p.eps) || !std::isfinite(p.alpha)) {
        throw std::invalid_argument("level-set parameters must be finite numbers (" + describe(p) +
                                    ")");
    }
    if (p.eps < 0.0F) {
        throw std::invalid_argument("eps must be >= 0 (got " + std::to_string(p.eps) + ")");
    }
    if (p.alpha < 0.0F || p.alpha > 1.0F) {
        throw std::invalid_argument("alpha must be in [0, 1] (got " + std::to_string(p.alpha) +
                                    ")");
    }
}

TimeStepRule timeStepRule(const LevelSetParams& p) {
    validateParams(p);
    TimeStepRule rule;
    rule.fixedRate = kRescaleWeight * kPhiFar / rule.courant + (1.0F - p.alpha) * 6.0F;
    return rule;
}

float stableTimeStep(const TimeStepRule& rule, float maxDataRate) {
    return 1.0F / (maxDataRate / rule.courant + rule.fixedRate);
}

glm::vec3 sphereScale(const glm::dvec3& spacing) {
    for (int a = 0; a < 3; ++a) {
        if (!std::isfinite(spacing[a]) || spacing[a] <= 0.0) {
            return glm::vec3(1.0F);
        }
    }
    const double finest = std::min({spacing.x, spacing.y, spacing.z});
    return glm::vec3(spacing / finest);
}

float sphereDistance(const Sphere& s, const glm::vec3& voxel, const glm::vec3& scale) {
    const glm::vec3 q = voxel - s.centre;
    const float n = sphereNorm(q, scale);
    // f = |q * scale| - r has gradient q * scale^2 / n: f / |grad f| is the distance in voxel
    // steps near the surface; at the centre, the nearest surface lies along the coarsest axis.
    const float g =
        n > 0.0F ? glm::length(q * scale * scale) / n : std::max({scale.x, scale.y, scale.z});
    return (n - s.radius) / g;
}

VoxelBox sphereVoxelBox(const Sphere& s, const glm::vec3& scale, const glm::ivec3& dims) {
    const glm::dvec3 c(s.centre);
    const glm::dvec3 half = static_cast<double>(s.radius) / glm::dvec3(scale);
    return {glm::max(glm::ivec3(glm::ceil(c - half)), glm::ivec3(0)),
            glm::min(glm::ivec3(glm::floor(c + half)), dims - 1)};
}

void validateSphere(const Sphere& s, const glm::ivec3& dims) {
    if (!std::isfinite(s.radius) || s.radius <= 0.0F) {
        throw std::invalid_argument("sphere radius must be a positive number of voxels (got " +
                                    std::to_string(s.radius) + ")");
    }
    const float diagonal = glm::length(glm::vec3(dims));
    if (s.radius > diagonal) {
        std::ostringstream msg;
        msg << "sphere radius " << s.radius << " voxels is larger than the volume's diagonal ("
            << diagonal << " voxels for " << dims.x << " x " << dims.y << " x " << dims.z << ")";
        throw std::invalid_argument(msg.str());
    }
    for (int a = 0; a < 3; ++a) {
        if (!std::isfinite(s.centre[a]) || s.centre[a] < 0.0F ||
            s.centre[a] > static_cast<float>(dims[a] - 1)) {
            std::ostringstream msg;
            msg << "sphere centre (" << s.centre.x << ", " << s.centre.y << ", " << s.centre.z
                << ") lies outside the volume (" << dims.x << " x " << dims.y << " x " << dims.z
                << " voxels)";
            throw std::invalid_argument(msg.str());
        }
    }
}

void validateBarrier(const Barrier& b, const glm::ivec3& dims) {
    validateSphere(b.sphere, dims);
    if (!b.tissue) {
        return;
    }
    if (!b.keep) {
        throw std::invalid_argument("only a keeping barrier carries a tissue level");
    }
    const float diagonal = glm::length(glm::vec3(dims));
    if (!std::isfinite(b.tissue->level) || !std::isfinite(b.tissue->reach) ||
        b.tissue->reach <= 0.0F || b.tissue->reach > diagonal) {
        std::ostringstream msg;
        msg << "a barrier's tissue level needs a finite level and a reach of (0, " << diagonal
            << "] voxels (got " << b.tissue->level << " within " << b.tissue->reach << ")";
        throw std::invalid_argument(msg.str());
    }
}

std::string describe(const LevelSetParams& p) {
    std::ostringstream s;
    s << "T=" << p.T << " eps=" << p.eps << " alpha=" << p.alpha;
    return s.str();
}

} // namespace steerseg::model
