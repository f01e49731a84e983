#include "session/speed_probe.hpp"

#include "session/probe.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace steerseg::session {

SpeedProbe probeSpeed(const Volume& volume, const model::Sphere& sphere) {
    model::validateSphere(sphere, volume.dims());
    const glm::vec3 scale = model::sphereScale(volume.geometry().spacing);
    const auto [lo, hi] = model::sphereVoxelBox(sphere, scale, volume.dims());
    const auto inside = [&](int i, int j, int k) {
        return model::sphereHolds(sphere, glm::dvec3(i, j, k), scale);
    };
    double sum = 0.0;
    double sumSq = 0.0;
    double diffSq = 0.0;
    std::size_t n = 0;
    std::size_t pairs = 0;
    for (int k = lo.z; k <= hi.z; ++k) {
        for (int j = lo.y; j <= hi.y; ++j) {
            for (int i = lo.x; i <= hi.x; ++i) {
                if (!inside(i, j, k)) {
                    continue;
                }
                const double v = volume.valueAt(i, j, k);
                sum += v;
                sumSq += v * v;
                ++n;
                const glm::ivec3 next[3] = {{i + 1, j, k}, {i, j + 1, k}, {i, j, k + 1}};
                for (const glm::ivec3& q : next) {
                    if (q.x <= hi.x && q.y <= hi.y && q.z <= hi.z && inside(q.x, q.y, q.z)) {
                        const double d = volume.valueAt(q.x, q.y, q.z) - v;
                        diffSq += d * d;
                        ++pairs;
                    }
                }
            }
        }
    }
    if (n < 2 || pairs == 0) {
        throw std::invalid_argument("probe: the sphere holds fewer than 2 voxels; give a radius "
                                    ">= 1");
    }
    SpeedProbe p;
    p.count = n;
    p.mean = sum / static_cast<double>(n);
    p.stddev = std::sqrt(std::max(0.0, sumSq / static_cast<double>(n) - p.mean * p.mean));
    p.noise = std::sqrt(diffSq / static_cast<double>(pairs) / 2.0);
    const SuggestedSpeed s = suggestSpeed({p.mean, p.stddev, n}, kEpsFactor);
    p.T = s.T;
    p.eps = std::max(s.eps, kEpsFloor);
    // A noiseless region (a phantom) would give K = kappa = 0, which no speed accepts.
    const double noise = std::max(p.noise, kNoiseFloor);
    p.conductance = kConductanceFactor * noise;
    p.kappa = kKappaFactor * noise;
    return p;
}

} // namespace steerseg::session
