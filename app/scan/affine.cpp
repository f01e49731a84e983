#include "scan/affine.hpp"

#include "scan/load_checks.hpp"

#include <cmath>

namespace steerseg::scan {

Affine affineOf(const Geometry& geometry) {
    Affine a;
    for (int c = 0; c < 3; ++c) {
        a.linear[c] = geometry.direction[c] * geometry.spacing[c];
    }
    a.offset = geometry.origin;
    return a;
}

Geometry geometryFromAffine(const std::filesystem::path& path, const Affine& affine,
                            const glm::ivec3& dims) {
    Geometry g;
    g.dims = dims;
    g.origin = affine.offset;
    for (int c = 0; c < 3; ++c) {
        const double len = glm::length(affine.linear[c]);
        g.spacing[c] = len;
        // A zero column keeps a unit axis so that checkGeometry reports the spacing, not NaNs.
        g.direction[c] =
            len > 0.0 && std::isfinite(len) ? affine.linear[c] / len : glm::dmat3(1.0)[c];
    }
    checkGeometry(path, g);
    return g;
}

Affine flipRasLps(const Affine& affine) {
    const glm::dmat3 flip(glm::dvec3(-1.0, 0.0, 0.0), glm::dvec3(0.0, -1.0, 0.0),
                          glm::dvec3(0.0, 0.0, 1.0));
    return {flip * affine.linear, flip * affine.offset};
}

bool hasOrthogonalColumns(const glm::dmat3& m, double tolerance) {
    for (int c = 0; c < 3; ++c) {
        const double lc = glm::length(m[c]);
        if (!(lc > 0.0) || !std::isfinite(lc)) {
            return false;
        }
        for (int d = c + 1; d < 3; ++d) {
            const double ld = glm::length(m[d]);
            if (!(ld > 0.0) || !std::isfinite(ld) ||
                std::abs(glm::dot(m[c], m[d])) / (lc * ld) > tolerance) {
                return false;
            }
        }
    }
    return true;
}

} // namespace steerseg::scan
