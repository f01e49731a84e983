#include "session/probe.hpp"

#include "core/single_outlier.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <optional>
#include <stdexcept>
#include <vector>

namespace steerseg::session {

ProbeStats probe(const Volume& volume, const glm::dvec3& index, double radiusMm, Stray stray) {
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
    std::vector<double> values;
    for (int k = lo.z; k <= hi.z; ++k) {
        for (int j = lo.y; j <= hi.y; ++j) {
            for (int i = lo.x; i <= hi.x; ++i) {
                const glm::dvec3 d = (glm::dvec3(i, j, k) - index) * g.spacing;
                if (glm::dot(d, d) <= radiusMm * radiusMm) {
                    values.push_back(volume.valueAt(i, j, k));
                }
            }
        }
    }
    // A probe is small (19 voxels at 5 mm on a 3 mm CT), and one stray voxel in it (contrast, a
    // calcification, metal) sets the spread, so eps, for the whole run: one of 600 HU beside 18
    // of -49 to 34 gave eps 269 on a kidney, and the front filled the abdomen. Grubbs' test
    // leaves out such a voxel; only one, so that a tissue's real tails (partial volume) stay
    // (docs/steering.md, "A stray voxel in the probe").
    ProbeStats s;
    const auto outlier = stray == Stray::LeaveOut ? singleOutlier(values) : std::nullopt;
    if (outlier) {
        values.erase(values.begin() + static_cast<std::ptrdiff_t>(*outlier));
        s.leftOut = 1;
    }
    s.count = values.size();
    if (s.count > 0) {
        double sum = 0.0;
        for (const double v : values) {
            sum += v;
        }
        s.mean = sum / static_cast<double>(s.count);
        double squares = 0.0;
        for (const double v : values) {
            squares += (v - s.mean) * (v - s.mean);
        }
        s.stddev = std::sqrt(squares / static_cast<double>(s.count));
    }
    return s;
}

SuggestedSpeed suggestSpeed(const ProbeStats& stats, double factor) {
    return {stats.mean, stats.stddev * factor};
}

} // namespace steerseg::session
