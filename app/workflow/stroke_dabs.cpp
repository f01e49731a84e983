#include "workflow/stroke_dabs.hpp"

#include <cmath>

namespace steerseg::workflow {

std::optional<std::vector<glm::dvec3>> strokeDabs(std::span<const glm::dvec3> points,
                                                  double spacing, std::size_t maxDabs,
                                                  const glm::dvec3& scale) {
    std::vector<glm::dvec3> dabs;
    if (points.empty()) {
        return dabs;
    }
    if (maxDabs == 0) {
        return std::nullopt;
    }
    dabs.push_back(points.front());
    for (std::size_t p = 1; p < points.size(); ++p) {
        const glm::dvec3 from = dabs.back();
        const glm::dvec3 to = points[p];
        const double length = glm::length((to - from) * scale);
        if (length < spacing) {
            continue;
        }
        // ceil(length / spacing) equal steps end exactly on the point, none longer than spacing.
        const double steps = std::ceil(length / spacing);
        if (steps > static_cast<double>(maxDabs - dabs.size())) {
            return std::nullopt;
        }
        const auto n = static_cast<std::size_t>(steps);
        for (std::size_t s = 1; s <= n; ++s) {
            dabs.push_back(from + (to - from) * (static_cast<double>(s) / steps));
        }
    }
    if (dabs.size() > maxDabs) {
        return std::nullopt;
    }
    return dabs;
}

} // namespace steerseg::workflow
