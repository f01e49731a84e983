#include "session/probe.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace steerseg::session {

ProbeStats probe(const Volume& volume, const glm::dvec3& index, double radiusMm) {
    if (!(radiusMm >= 0.0) || !std::isfinite(radiusMm) || !std::isfinite(index.x) ||
        !std::isfinite(index.y) || !std::isfinite(index.z)) {
        throw std::invalid_argument("probe: position and radius must be finite, radius >= 0");
    }
    const Geometry& g = volume.geometry();
    // Direction cosines are orthonormal, so distances in the world are index distances
    // scaled by the spacing.
    const glm::dvec3 reach = radiusMm / g.spacing;
    const glm::ivec3 lo = glm::max(glm::ivec3(glm::ceil(index - reach)), glm::ivec3(0));
    const glm::ivec3 hi = glm::min(glm::ivec3(glm::floor(index + reach)), g.dims - 1);
    double sum = 0.0;
    double sumSq = 0.0;
    std::size_t n = 0;
    for (int k = lo.z; k <= hi.z; ++k) {
        for (int j = lo.y; j <= hi.y; ++j) {
            for (int i = lo.x; i <= hi.x; ++i) {
                const glm::dvec3 d = (glm::dvec3(i, j, k) - index) * g.spacing;
                if (glm::dot(d, d) > radiusMm * radiusMm) {
                    continue;
                }
                const double v = volume.valueAt(i, j, k);
                sum += v;
                sumSq += v * v;
                ++n;
            }
        }
    }
    ProbeStats s;
    s.count = n;
    if (n > 0) {
        s.mean = sum / static_cast<double>(n);
        s.stddev = std::sqrt(std::max(0.0, sumSq / static_cast<double>(n) - s.mean * s.mean));
    }
    return s;
}

SuggestedSpeed suggestSpeed(const ProbeStats& stats, double factor) {
    return {stats.mean, stats.stddev * factor};
}

} // namespace steerseg::session
