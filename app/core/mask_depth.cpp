#include "core/mask_depth.hpp"

#include "core/mask_box.hpp"
#include "core/volume.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

namespace steerseg {

namespace {

constexpr double kFar = std::numeric_limits<double>::infinity();

// Felzenszwalb and Huttenlocher's squared distance along one line, in units of the line's
// voxel: d(p) = min over sites q of f(q) + (p - q)^2, with sites at -1 and n when `pad`.
// Sites with f = infinity are no sites at all.
void distanceAlongLine(std::vector<double>& line, bool pad, std::vector<double>& site,
                       std::vector<double>& value, std::vector<double>& from) {
    const int n = static_cast<int>(line.size());
    site.clear();
    value.clear();
    from.clear();
    const auto add = [&](double q, double fq) {
        while (!site.empty()) {
            const double v = site.back();
            const double s = ((fq + q * q) - (value.back() + v * v)) / (2.0 * (q - v));
            if (s <= from.back()) {
                site.pop_back();
                value.pop_back();
                from.pop_back();
            } else {
                from.push_back(s);
                break;
            }
        }
        if (site.empty()) {
            from.push_back(-kFar);
        }
        site.push_back(q);
        value.push_back(fq);
    };
    if (pad) {
        add(-1.0, 0.0);
    }
    for (int q = 0; q < n; ++q) {
        if (line[static_cast<std::size_t>(q)] < kFar) {
            add(q, line[static_cast<std::size_t>(q)]);
        }
    }
    if (pad) {
        add(n, 0.0);
    }
    if (site.empty()) {
        return; // no site on this line: every value stays infinite
    }
    std::size_t k = 0;
    for (int p = 0; p < n; ++p) {
        while (k + 1 < site.size() && from[k + 1] < p) {
            ++k;
        }
        const double dp = p - site[k];
        line[static_cast<std::size_t>(p)] = dp * dp + value[k];
    }
}

// The squared distances in mm, in place: `sq` holds 0 on a site and infinity elsewhere. Each
// line is worked in double; `Stored` is what the volume keeps between the axes' passes (float
// where only the distances near a small depth matter: half the memory on a large mask).
template <typename Stored>
void squaredDistancesMm(std::vector<Stored>& sq, const glm::ivec3& d, const glm::dvec3& spacingMm,
                        bool beyondIsSite) {
    std::vector<double> line;
    std::vector<double> site;
    std::vector<double> value;
    std::vector<double> from;
    // One pass per axis, in squared mm: each line's values scaled to its voxel and back.
    for (int axis = 0; axis < 3; ++axis) {
        const double s2 = spacingMm[axis] * spacingMm[axis];
        const int n = d[axis];
        const int a = (axis + 1) % 3;
        const int b = (axis + 2) % 3;
        line.resize(static_cast<std::size_t>(n));
        for (int u = 0; u < d[b]; ++u) {
            for (int w = 0; w < d[a]; ++w) {
                glm::ivec3 p(0);
                p[a] = w;
                p[b] = u;
                for (int q = 0; q < n; ++q) {
                    p[axis] = q;
                    line[static_cast<std::size_t>(q)] =
                        static_cast<double>(sq[linearIndex(d, p.x, p.y, p.z)]) / s2;
                }
                distanceAlongLine(line, beyondIsSite, site, value, from);
                for (int q = 0; q < n; ++q) {
                    p[axis] = q;
                    sq[linearIndex(d, p.x, p.y, p.z)] =
                        static_cast<Stored>(line[static_cast<std::size_t>(q)] * s2);
                }
            }
        }
    }
}

} // namespace

std::vector<float> distanceToSitesMm(const glm::ivec3& dims, const glm::dvec3& spacingMm,
                                     std::span<const std::uint8_t> sites, bool beyondIsSite) {
    std::vector<double> sq(sites.size());
    for (std::size_t v = 0; v < sq.size(); ++v) {
        sq[v] = sites[v] != 0 ? 0.0 : kFar;
    }
    squaredDistancesMm(sq, dims, spacingMm, beyondIsSite);
    std::vector<float> out(sq.size());
    for (std::size_t v = 0; v < sq.size(); ++v) {
        out[v] = static_cast<float>(std::sqrt(sq[v]));
    }
    return out;
}

std::vector<std::uint8_t> deeperThan(const glm::ivec3& dims, const glm::dvec3& spacingMm,
                                     std::span<const std::uint8_t> mask, double depthMm) {
    if (!std::isfinite(depthMm) || depthMm < 0.0) {
        throw std::invalid_argument("a depth must be a finite number of mm >= 0 (got " +
                                    std::to_string(depthMm) + ")");
    }
    const std::optional<MaskBox> box = maskBox(dims, mask); // refuses another size
    std::vector<std::uint8_t> deep(mask.size(), 0);
    if (!box) {
        return deep;
    }
    // One voxel of outside around the box, where the grid has it: the sites of the distance.
    const MaskBox around = grownWithin(*box, 1, dims);
    const glm::ivec3 lo = around.lo;
    const glm::ivec3 sub = boxDims(around);
    // Squared distances to the outside, the box's voxels only, compared in squared mm.
    std::vector<float> sq =
        cropMask(dims, mask, around, std::numeric_limits<float>::infinity(), 0.0F);
    squaredDistancesMm(sq, sub, spacingMm, false);
    const double limit = depthMm * depthMm;
    for (int k = 0; k < sub.z; ++k) {
        for (int j = 0; j < sub.y; ++j) {
            for (int i = 0; i < sub.x; ++i) {
                if (static_cast<double>(sq[linearIndex(sub, i, j, k)]) > limit) {
                    deep[linearIndex(dims, lo.x + i, lo.y + j, lo.z + k)] = 1;
                }
            }
        }
    }
    return deep;
}

} // namespace steerseg
