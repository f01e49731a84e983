#include "steering/click_robot.hpp"

#include "core/mask_box.hpp"
#include "core/mask_depth.hpp"
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

} // namespace

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
                                       const std::vector<std::uint8_t>& label,
                                       DepthMeasure measure) {
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
    const bool inMm = measure == DepthMeasure::Millimetres;
    const std::vector<float> depth =
        distanceToSitesMm(grid.dims, inMm ? grid.spacing : glm::dvec3(1.0), outside, true);
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
    // The brush is sized in mm whichever measure chose the voxel.
    const float depthMm =
        inMm ? bestDepth : distanceToSitesMm(grid.dims, grid.spacing, outside, true)[best];
    c.depthMm = static_cast<double>(depthMm);
    c.componentVoxels = voxels;
    return c;
}

std::optional<VoxelBox> labelBox(const MaskGrid& grid, const std::vector<std::uint8_t>& label) {
    if (const std::optional<MaskBox> box = maskBox(grid.dims, label)) {
        return VoxelBox{box->lo, box->hi};
    }
    return std::nullopt;
}

std::optional<RobotClick> initialClick(const MaskGrid& grid,
                                       const std::vector<std::uint8_t>& label) {
    return deepestClick(grid, label, label);
}

std::optional<RobotClick> correctionClick(const MaskGrid& grid,
                                          const std::vector<std::uint8_t>& mask,
                                          const std::vector<std::uint8_t>& label,
                                          DepthMeasure measure) {
    std::vector<std::uint8_t> error(mask.size());
    for (std::size_t v = 0; v < mask.size(); ++v) {
        error[v] = (mask[v] != 0) != (label[v] != 0) ? 1 : 0;
    }
    return deepestClick(grid, error, label, measure);
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
    const std::vector<float> toB = distanceToSitesMm(grid.dims, grid.spacing, sb, false);
    const std::vector<float> toA = distanceToSitesMm(grid.dims, grid.spacing, sa, false);
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
