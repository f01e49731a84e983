#include "steering/click_robot.hpp"

#include "model/level_set_params.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace steerseg::bench {

namespace {

constexpr double kFar = std::numeric_limits<double>::infinity();

std::size_t at(const glm::ivec3& d, int i, int j, int k) {
    return static_cast<std::size_t>(i) +
           static_cast<std::size_t>(d.x) *
               (static_cast<std::size_t>(j) +
                static_cast<std::size_t>(d.y) * static_cast<std::size_t>(k));
}

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

} // namespace

std::vector<float> distanceToSitesMm(const MaskGrid& grid, const std::vector<std::uint8_t>& sites,
                                     bool beyondIsSite) {
    const glm::ivec3 d = grid.dims;
    std::vector<double> sq(grid.count());
    for (std::size_t v = 0; v < sq.size(); ++v) {
        sq[v] = sites[v] != 0 ? 0.0 : kFar;
    }
    std::vector<double> line;
    std::vector<double> site;
    std::vector<double> value;
    std::vector<double> from;
    // One pass per axis, in squared mm: each line's values scaled to its voxel and back.
    for (int axis = 0; axis < 3; ++axis) {
        const double s2 = grid.spacing[axis] * grid.spacing[axis];
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
                    line[static_cast<std::size_t>(q)] = sq[at(d, p.x, p.y, p.z)] / s2;
                }
                distanceAlongLine(line, beyondIsSite, site, value, from);
                for (int q = 0; q < n; ++q) {
                    p[axis] = q;
                    sq[at(d, p.x, p.y, p.z)] = line[static_cast<std::size_t>(q)] * s2;
                }
            }
        }
    }
    std::vector<float> out(sq.size());
    for (std::size_t v = 0; v < sq.size(); ++v) {
        out[v] = static_cast<float>(std::sqrt(sq[v]));
    }
    return out;
}

std::vector<std::uint8_t> largestComponent(const MaskGrid& grid,
                                           const std::vector<std::uint8_t>& region) {
    const glm::ivec3 d = grid.dims;
    std::vector<std::uint32_t> label(grid.count(), 0);
    std::uint32_t best = 0;
    std::size_t bestSize = 0;
    std::uint32_t next = 0;
    std::vector<std::size_t> stack;
    for (std::size_t start = 0; start < region.size(); ++start) {
        if (region[start] == 0 || label[start] != 0) {
            continue;
        }
        ++next;
        std::size_t size = 0;
        label[start] = next;
        stack.push_back(start);
        while (!stack.empty()) {
            const std::size_t v = stack.back();
            stack.pop_back();
            ++size;
            const int i = static_cast<int>(v % static_cast<std::size_t>(d.x));
            const int j = static_cast<int>((v / static_cast<std::size_t>(d.x)) %
                                           static_cast<std::size_t>(d.y));
            const int k = static_cast<int>(
                v / (static_cast<std::size_t>(d.x) * static_cast<std::size_t>(d.y)));
            for (int dk = -1; dk <= 1; ++dk) {
                for (int dj = -1; dj <= 1; ++dj) {
                    for (int di = -1; di <= 1; ++di) {
                        const int ni = i + di;
                        const int nj = j + dj;
                        const int nk = k + dk;
                        if (ni < 0 || nj < 0 || nk < 0 || ni >= d.x || nj >= d.y || nk >= d.z) {
                            continue;
                        }
                        const std::size_t u = at(d, ni, nj, nk);
                        if (region[u] != 0 && label[u] == 0) {
                            label[u] = next;
                            stack.push_back(u);
                        }
                    }
                }
            }
        }
        if (size > bestSize) { // strictly larger: of equal ones the first found stays
            best = next;
            bestSize = size;
        }
    }
    std::vector<std::uint8_t> out(grid.count(), 0);
    if (best != 0) {
        for (std::size_t v = 0; v < out.size(); ++v) {
            out[v] = label[v] == best ? 1 : 0;
        }
    }
    return out;
}

std::optional<RobotClick> deepestClick(const MaskGrid& grid,
                                       const std::vector<std::uint8_t>& region,
                                       const std::vector<std::uint8_t>& label) {
    const std::vector<std::uint8_t> component = largestComponent(grid, region);
    std::vector<std::uint8_t> outside(component.size());
    std::size_t voxels = 0;
    for (std::size_t v = 0; v < component.size(); ++v) {
        outside[v] = component[v] != 0 ? 0 : 1;
        voxels += component[v];
    }
    if (voxels == 0) {
        return std::nullopt;
    }
    const std::vector<float> depth = distanceToSitesMm(grid, outside, true);
    std::size_t best = 0;
    float bestDepth = -1.0F;
    for (std::size_t v = 0; v < component.size(); ++v) {
        if (component[v] != 0 && depth[v] > bestDepth) {
            best = v;
            bestDepth = depth[v];
        }
    }
    const glm::ivec3 d = grid.dims;
    RobotClick c;
    c.voxel = {
        static_cast<int>(best % static_cast<std::size_t>(d.x)),
        static_cast<int>((best / static_cast<std::size_t>(d.x)) % static_cast<std::size_t>(d.y)),
        static_cast<int>(best / (static_cast<std::size_t>(d.x) * static_cast<std::size_t>(d.y)))};
    c.positive = label[best] != 0;
    c.depthMm = static_cast<double>(bestDepth);
    c.componentVoxels = voxels;
    return c;
}

std::optional<VoxelBox> labelBox(const MaskGrid& grid, const std::vector<std::uint8_t>& label) {
    std::optional<VoxelBox> box;
    std::size_t v = 0;
    for (int k = 0; k < grid.dims.z; ++k) {
        for (int j = 0; j < grid.dims.y; ++j) {
            for (int i = 0; i < grid.dims.x; ++i, ++v) {
                if (label[v] == 0) {
                    continue;
                }
                const glm::ivec3 p(i, j, k);
                if (!box) {
                    box = VoxelBox{p, p};
                }
                box->lo = glm::min(box->lo, p);
                box->hi = glm::max(box->hi, p);
            }
        }
    }
    return box;
}

std::optional<RobotClick> initialClick(const MaskGrid& grid,
                                       const std::vector<std::uint8_t>& label) {
    return deepestClick(grid, label, label);
}

std::optional<RobotClick> correctionClick(const MaskGrid& grid,
                                          const std::vector<std::uint8_t>& mask,
                                          const std::vector<std::uint8_t>& label) {
    std::vector<std::uint8_t> error(mask.size());
    for (std::size_t v = 0; v < mask.size(); ++v) {
        error[v] = (mask[v] != 0) != (label[v] != 0) ? 1 : 0;
    }
    return deepestClick(grid, error, label);
}

double brushRadius(const MaskGrid& grid, const RobotClick& click, double maxRadius) {
    const double finest = std::min({grid.spacing.x, grid.spacing.y, grid.spacing.z});
    return std::clamp(click.depthMm / finest, 1.0, std::max(1.0, maxRadius));
}

double dice(const std::vector<std::uint8_t>& a, const std::vector<std::uint8_t>& b) {
    std::size_t na = 0;
    std::size_t nb = 0;
    std::size_t both = 0;
    for (std::size_t v = 0; v < a.size(); ++v) {
        na += a[v] != 0 ? 1 : 0;
        nb += b[v] != 0 ? 1 : 0;
        both += a[v] != 0 && b[v] != 0 ? 1 : 0;
    }
    return na + nb == 0 ? 1.0 : 2.0 * static_cast<double>(both) / static_cast<double>(na + nb);
}

namespace {

std::vector<std::uint8_t> surfaceOf(const MaskGrid& grid, const std::vector<std::uint8_t>& m) {
    const glm::ivec3 d = grid.dims;
    std::vector<std::uint8_t> s(m.size(), 0);
    for (int k = 0; k < d.z; ++k) {
        for (int j = 0; j < d.y; ++j) {
            for (int i = 0; i < d.x; ++i) {
                const std::size_t v = at(d, i, j, k);
                if (m[v] == 0) {
                    continue;
                }
                const bool edge =
                    i == 0 || j == 0 || k == 0 || i == d.x - 1 || j == d.y - 1 || k == d.z - 1;
                s[v] = edge || m[at(d, i - 1, j, k)] == 0 || m[at(d, i + 1, j, k)] == 0 ||
                               m[at(d, i, j - 1, k)] == 0 || m[at(d, i, j + 1, k)] == 0 ||
                               m[at(d, i, j, k - 1)] == 0 || m[at(d, i, j, k + 1)] == 0
                           ? 1
                           : 0;
            }
        }
    }
    return s;
}

} // namespace

double surfaceDice(const MaskGrid& grid, const std::vector<std::uint8_t>& a,
                   const std::vector<std::uint8_t>& b, double toleranceMm) {
    const std::vector<std::uint8_t> sa = surfaceOf(grid, a);
    const std::vector<std::uint8_t> sb = surfaceOf(grid, b);
    const std::size_t na = static_cast<std::size_t>(std::count(sa.begin(), sa.end(), 1));
    const std::size_t nb = static_cast<std::size_t>(std::count(sb.begin(), sb.end(), 1));
    if (na + nb == 0) {
        return 1.0;
    }
    if (na == 0 || nb == 0) {
        return 0.0;
    }
    const std::vector<float> toB = distanceToSitesMm(grid, sb, false);
    const std::vector<float> toA = distanceToSitesMm(grid, sa, false);
    std::size_t close = 0;
    for (std::size_t v = 0; v < sa.size(); ++v) {
        close += sa[v] != 0 && static_cast<double>(toB[v]) <= toleranceMm ? 1 : 0;
        close += sb[v] != 0 && static_cast<double>(toA[v]) <= toleranceMm ? 1 : 0;
    }
    return static_cast<double>(close) / static_cast<double>(na + nb);
}

void paintSphere(const MaskGrid& grid, std::vector<std::uint8_t>& mask, const glm::dvec3& centre,
                 double radius, std::uint8_t value) {
    const glm::ivec3 d = grid.dims;
    const glm::dvec3 scale(model::sphereScale(grid.spacing));
    const glm::ivec3 lo = glm::max(glm::ivec3(glm::ceil(centre - radius / scale)), glm::ivec3(0));
    const glm::ivec3 hi = glm::min(glm::ivec3(glm::floor(centre + radius / scale)), d - 1);
    for (int k = lo.z; k <= hi.z; ++k) {
        for (int j = lo.y; j <= hi.y; ++j) {
            for (int i = lo.x; i <= hi.x; ++i) {
                if (glm::length((glm::dvec3(i, j, k) - centre) * scale) <= radius) {
                    mask[at(d, i, j, k)] = value;
                }
            }
        }
    }
}

ChallengeScores challengeScores(const std::vector<double>& dices, const std::vector<double>& nsds,
                                std::size_t corrections) {
    const std::size_t steps = std::min({dices.size(), nsds.size(), corrections + 1});
    if (steps < 2) {
        return {};
    }
    std::vector<double> dsc(dices.begin() + 1, dices.begin() + static_cast<std::ptrdiff_t>(steps));
    std::vector<double> nsd(nsds.begin() + 1, nsds.begin() + static_cast<std::ptrdiff_t>(steps));
    for (std::size_t n = 0; n < nsd.size(); ++n) {
        nsd[n] = dsc[n] > 0.2 ? nsd[n] : 0.0;
    }
    return {diceAuc(dsc, dsc.size()), diceAuc(nsd, nsd.size()), dsc.back(), nsd.back()};
}

double diceAuc(const std::vector<double>& dices, std::size_t points) {
    const std::size_t n = std::min(points, dices.size());
    double auc = 0.0;
    for (std::size_t p = 1; p < n; ++p) {
        auc += 0.5 * (dices[p - 1] + dices[p]);
    }
    return auc;
}

} // namespace steerseg::bench
