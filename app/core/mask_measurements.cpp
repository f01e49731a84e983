// Diameters from convex hulls: the farthest two points of a set are vertices of its convex hull,
// and a 3D hull's vertices are hull vertices of the slices through them, so exact answers over
// voxel centres need only the slices' hulls, never all pairs of voxels.
#include "core/mask_measurements.hpp"

#include "core/mask_field.hpp"
#include "core/surface_mesh.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

namespace steerseg {

namespace {

// A point of a slice: whole voxel indices along the slice's two axes, and millimetres in an
// orthonormal basis of the slice's plane.
struct SlicePoint {
    long long a = 0;
    long long b = 0;
    glm::dvec2 mm{0.0};
};

// The slice's plane in millimetres: index steps along axes a and b as 2D vectors in a basis of
// the plane, exact for a grid whose axes are not at right angles too.
struct PlaneBasis {
    glm::dvec2 stepA{0.0};
    glm::dvec2 stepB{0.0};

    PlaneBasis(const Geometry& g, int axisA, int axisB) {
        const glm::dvec3 ca = g.direction[axisA] * g.spacing[axisA];
        const glm::dvec3 cb = g.direction[axisB] * g.spacing[axisB];
        const glm::dvec3 e1 = glm::normalize(ca);
        const glm::dvec3 rest = cb - glm::dot(cb, e1) * e1;
        const double restLength = glm::length(rest);
        const glm::dvec3 e2 = restLength > 0.0 ? rest / restLength : glm::dvec3(0.0);
        stepA = {glm::dot(ca, e1), 0.0};
        stepB = {glm::dot(cb, e1), glm::dot(cb, e2)};
    }
    [[nodiscard]] glm::dvec2 mm(long long a, long long b) const {
        return static_cast<double>(a) * stepA + static_cast<double>(b) * stepB;
    }
};

long long cross(const SlicePoint& o, const SlicePoint& p, const SlicePoint& q) {
    return (p.a - o.a) * (q.b - o.b) - (p.b - o.b) * (q.a - o.a);
}

// Andrew's monotone chain in whole index coordinates (exact), counter-clockwise, collinear
// points dropped; one point, or two for a line of voxels.
std::vector<SlicePoint> convexHull(std::vector<SlicePoint> points) {
    std::sort(points.begin(), points.end(), [](const SlicePoint& p, const SlicePoint& q) {
        return p.a != q.a ? p.a < q.a : p.b < q.b;
    });
    points.erase(std::unique(points.begin(), points.end(),
                             [](const SlicePoint& p, const SlicePoint& q) {
                                 return p.a == q.a && p.b == q.b;
                             }),
                 points.end());
    if (points.size() < 3) {
        return points;
    }
    std::vector<SlicePoint> hull(2 * points.size());
    std::size_t n = 0;
    for (const SlicePoint& p : points) {
        while (n >= 2 && cross(hull[n - 2], hull[n - 1], p) <= 0) {
            --n;
        }
        hull[n++] = p;
    }
    const std::size_t lower = n + 1;
    for (auto it = points.rbegin() + 1; it != points.rend(); ++it) {
        while (n >= lower && cross(hull[n - 2], hull[n - 1], *it) <= 0) {
            --n;
        }
        hull[n++] = *it;
    }
    hull.resize(n - 1);
    return hull;
}

// The farthest pair of a slice's hull vertices (a few hundred at most: all pairs is cheap).
std::pair<std::size_t, std::size_t> farthestPair(const std::vector<SlicePoint>& hull,
                                                 double& length) {
    std::pair<std::size_t, std::size_t> best{0, 0};
    double best2 = 0.0;
    for (std::size_t p = 0; p < hull.size(); ++p) {
        for (std::size_t q = p + 1; q < hull.size(); ++q) {
            const glm::dvec2 d = hull[q].mm - hull[p].mm;
            const double d2 = glm::dot(d, d);
            if (d2 > best2) {
                best2 = d2;
                best = {p, q};
            }
        }
    }
    length = std::sqrt(best2);
    return best;
}

// A point on the hull's boundary: millimetres in the plane and index coordinates (a, b).
struct BoundaryPoint {
    glm::dvec2 mm{0.0};
    glm::dvec2 index{0.0};
};

// The longest chord of a convex polygon along `v` (at right angles to `u`). Its length is a
// concave, piecewise linear function of the chord's place along u, bent only at vertices, so
// the longest runs through a vertex.
std::pair<BoundaryPoint, BoundaryPoint> longestChord(const std::vector<SlicePoint>& hull,
                                                     const glm::dvec2& u, const glm::dvec2& v) {
    const auto at = [](const SlicePoint& p) {
        return BoundaryPoint{p.mm, {static_cast<double>(p.a), static_cast<double>(p.b)}};
    };
    std::pair<BoundaryPoint, BoundaryPoint> best{at(hull.front()), at(hull.front())};
    double bestLength = 0.0;
    const std::size_t n = hull.size();
    for (const SlicePoint& through : hull) {
        const double s = glm::dot(through.mm, u);
        BoundaryPoint low = at(through);
        BoundaryPoint high = low;
        for (std::size_t e = 0; e < n && n > 1; ++e) {
            const SlicePoint& p = hull[e];
            const SlicePoint& q = hull[(e + 1) % n];
            const double sp = glm::dot(p.mm, u) - s;
            const double sq = glm::dot(q.mm, u) - s;
            if ((sp > 0.0 && sq > 0.0) || (sp < 0.0 && sq < 0.0)) {
                continue;
            }
            // An edge along the chord gives both its ends; one that crosses it, the crossing.
            const double t = sp == sq ? 0.0 : sp / (sp - sq);
            for (const double f :
                 sp == sq ? std::array<double, 2>{0.0, 1.0} : std::array<double, 2>{t, t}) {
                const BoundaryPoint x{p.mm + f * (q.mm - p.mm),
                                      at(p).index + f * (at(q).index - at(p).index)};
                if (glm::dot(x.mm, v) < glm::dot(low.mm, v)) {
                    low = x;
                }
                if (glm::dot(x.mm, v) > glm::dot(high.mm, v)) {
                    high = x;
                }
            }
        }
        const double length = glm::dot(high.mm - low.mm, v);
        if (length > bestLength) {
            bestLength = length;
            best = {low, high};
        }
    }
    return best;
}

MeasuredLine lineBetween(const Geometry& g, const glm::dvec3& from, const glm::dvec3& to) {
    MeasuredLine line;
    line.index = {from, to};
    line.world = {g.indexToWorld(from), g.indexToWorld(to)};
    line.lengthMm = glm::distance(line.world[0], line.world[1]);
    return line;
}

// The farthest two of the candidate voxel centres (world mm), exactly. Sorted by distance from
// their centroid, a point p can reach no farther than |p - c| + the largest such distance, so
// the search stops once that bound cannot beat the best pair found.
std::pair<std::size_t, std::size_t> farthestPair3d(const std::vector<glm::dvec3>& points) {
    if (points.empty()) {
        return {0, 0};
    }
    glm::dvec3 centroid(0.0);
    for (const glm::dvec3& p : points) {
        centroid += p / static_cast<double>(points.size());
    }
    std::vector<std::pair<double, std::size_t>> order(points.size());
    for (std::size_t n = 0; n < points.size(); ++n) {
        order[n] = {glm::distance(points[n], centroid), n};
    }
    std::sort(order.begin(), order.end(), [](const auto& x, const auto& y) {
        return x.first != y.first ? x.first > y.first : x.second < y.second;
    });
    const double reach = order.front().first;
    std::pair<std::size_t, std::size_t> best{order.front().second, order.front().second};
    double bestLength = 0.0;
    for (std::size_t p = 0; p < order.size(); ++p) {
        if (order[p].first + reach <= bestLength) {
            break;
        }
        const glm::dvec3& a = points[order[p].second];
        for (std::size_t q = p + 1; q < order.size(); ++q) {
            if (order[p].first + order[q].first <= bestLength) {
                break;
            }
            const double d = glm::distance(a, points[order[q].second]);
            if (d > bestLength) {
                bestLength = d;
                best = {order[p].second, order[q].second};
            }
        }
    }
    return best;
}

MaskIntensity intensityOver(const Volume& scan, std::span<const std::uint8_t> mask,
                            std::uint64_t voxels) {
    MaskIntensity out;
    out.min = std::numeric_limits<double>::infinity();
    out.max = -std::numeric_limits<double>::infinity();
    double sum = 0.0;
    for (std::size_t n = 0; n < mask.size(); ++n) {
        if (mask[n] != 0) {
            const double v = scan.realAt(n);
            sum += v;
            out.min = std::min(out.min, v);
            out.max = std::max(out.max, v);
        }
    }
    out.mean = sum / static_cast<double>(voxels);
    // Around the mean, a second pass: the one-pass sum of squares loses small spreads of large
    // values (HU around 1000) to cancellation.
    double squares = 0.0;
    for (std::size_t n = 0; n < mask.size(); ++n) {
        if (mask[n] != 0) {
            const double d = scan.realAt(n) - out.mean;
            squares += d * d;
        }
    }
    out.sd = std::sqrt(squares / static_cast<double>(voxels));
    return out;
}

} // namespace

int axialSliceAxis(const Geometry& geometry) {
    int best = 0;
    for (int a = 1; a < 3; ++a) {
        if (std::abs(geometry.direction[a].z) > std::abs(geometry.direction[best].z)) {
            best = a;
        }
    }
    return best;
}

MaskMeasurements measureMask(const Volume& scan, std::span<const std::uint8_t> mask) {
    const Geometry& g = scan.geometry();
    if (mask.size() != g.voxelCount()) {
        throw std::invalid_argument("the mask has " + std::to_string(mask.size()) +
                                    " voxels for a scan of " + std::to_string(g.voxelCount()));
    }
    MaskMeasurements m;
    m.voxels = static_cast<std::uint64_t>(
        std::count_if(mask.begin(), mask.end(), [](std::uint8_t v) { return v != 0; }));
    if (m.voxels == 0) {
        throw std::invalid_argument("no voxel of the mask is inside");
    }
    m.volumeMl =
        static_cast<double>(m.voxels) * std::abs(g.spacing.x * g.spacing.y * g.spacing.z) / 1000.0;
    m.surfaceAreaMm2 = surfaceArea(extractSurface(g, maskToField(g, mask)));
    m.intensity = intensityOver(scan, mask, m.voxels);

    // Each row of a slice adds only its first and last inside voxel: the others are never
    // hull vertices.
    const int s = axialSliceAxis(g);
    const int axisA = s == 0 ? 1 : 0;
    const int axisB = s == 2 ? 1 : 2;
    const int slices = g.dims[s];
    const int rows = g.dims[axisB];
    std::vector<int> first(static_cast<std::size_t>(slices) * static_cast<std::size_t>(rows),
                           std::numeric_limits<int>::max());
    std::vector<int> last(first.size(), -1);
    for (int k = 0; k < g.dims.z; ++k) {
        for (int j = 0; j < g.dims.y; ++j) {
            const std::uint8_t* row = mask.data() + linearIndex(g.dims, 0, j, k);
            for (int i = 0; i < g.dims.x; ++i) {
                if (row[i] == 0) {
                    continue;
                }
                const glm::ivec3 p(i, j, k);
                const std::size_t at =
                    static_cast<std::size_t>(p[s]) * static_cast<std::size_t>(rows) +
                    static_cast<std::size_t>(p[axisB]);
                first[at] = std::min(first[at], p[axisA]);
                last[at] = std::max(last[at], p[axisA]);
            }
        }
    }

    const PlaneBasis plane(g, axisA, axisB);
    const auto indexOf = [&](int slice, double a, double b) {
        glm::dvec3 p(0.0);
        p[s] = slice;
        p[axisA] = a;
        p[axisB] = b;
        return p;
    };
    std::vector<glm::dvec3> candidates; // every slice's hull vertices, world mm
    std::vector<glm::dvec3> candidateIndex;
    double bestLength = -1.0;
    std::vector<SlicePoint> bestHull;
    for (int slice = 0; slice < slices; ++slice) {
        std::vector<SlicePoint> points;
        for (int b = 0; b < rows; ++b) {
            const std::size_t at =
                static_cast<std::size_t>(slice) * static_cast<std::size_t>(rows) +
                static_cast<std::size_t>(b);
            if (last[at] < 0) {
                continue;
            }
            for (const int a : {first[at], last[at]}) {
                points.push_back({a, b, plane.mm(a, b)});
            }
        }
        if (points.empty()) {
            continue;
        }
        std::vector<SlicePoint> hull = convexHull(std::move(points));
        for (const SlicePoint& p : hull) {
            const glm::dvec3 index =
                indexOf(slice, static_cast<double>(p.a), static_cast<double>(p.b));
            candidateIndex.push_back(index);
            candidates.push_back(g.indexToWorld(index));
        }
        double length = 0.0;
        const auto [p, q] = farthestPair(hull, length);
        if (length > bestLength) {
            bestLength = length;
            m.axial.slice = slice;
            m.axial.longest = lineBetween(
                g, indexOf(slice, static_cast<double>(hull[p].a), static_cast<double>(hull[p].b)),
                indexOf(slice, static_cast<double>(hull[q].a), static_cast<double>(hull[q].b)));
            bestHull = std::move(hull);
        }
    }
    m.axial.sliceAxis = s;

    // At right angles to the longest, in the slice's plane; a single voxel has no direction,
    // and any will do for its chord of zero.
    const auto& ends = m.axial.longest.index;
    const glm::dvec2 along = (ends[1][axisA] - ends[0][axisA]) * plane.stepA +
                             (ends[1][axisB] - ends[0][axisB]) * plane.stepB;
    const glm::dvec2 u = glm::length(along) > 0.0 ? glm::normalize(along) : glm::dvec2(1.0, 0.0);
    const glm::dvec2 v(-u.y, u.x);
    const auto [low, high] = longestChord(bestHull, u, v);
    m.axial.perpendicular = lineBetween(g, indexOf(m.axial.slice, low.index.x, low.index.y),
                                        indexOf(m.axial.slice, high.index.x, high.index.y));

    const auto [p, q] = farthestPair3d(candidates);
    m.longest3d = lineBetween(g, candidateIndex[p], candidateIndex[q]);
    return m;
}

} // namespace steerseg
