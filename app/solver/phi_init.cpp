#include "solver/phi_init.hpp"

#include "core/volume.hpp"
#include "solver/phi_stencil.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>
#include <string>

namespace steerseg::solver {

namespace {

std::size_t voxelCount(const glm::ivec3& d) {
    return static_cast<std::size_t>(d.x) * static_cast<std::size_t>(d.y) *
           static_cast<std::size_t>(d.z);
}

} // namespace

std::vector<float> maskToPhi(std::span<const std::uint8_t> mask, const glm::ivec3& d) {
    if (mask.size() != voxelCount(d)) {
        throw std::invalid_argument("mask has " + std::to_string(mask.size()) +
                                    " voxels but the volume has " + std::to_string(voxelCount(d)));
    }
    // |phi| starts clamped; each boundary voxel (a face neighbour has the other label) lowers
    // |phi| of the other label's voxels within reach. Cost follows the surface, not the volume.
    std::vector<float> magnitude(mask.size(), model::kPhiFar);
    const int reach = static_cast<int>(std::ceil(model::kPhiFar + 0.5F));
    auto label = [&](int i, int j, int k) { return mask[linearIndex(d, i, j, k)] != 0; };
    for (int k = 0; k < d.z; ++k) {
        for (int j = 0; j < d.y; ++j) {
            for (int i = 0; i < d.x; ++i) {
                const bool in = label(i, j, k);
                const bool boundary = (i > 0 && label(i - 1, j, k) != in) ||
                                      (i + 1 < d.x && label(i + 1, j, k) != in) ||
                                      (j > 0 && label(i, j - 1, k) != in) ||
                                      (j + 1 < d.y && label(i, j + 1, k) != in) ||
                                      (k > 0 && label(i, j, k - 1) != in) ||
                                      (k + 1 < d.z && label(i, j, k + 1) != in);
                if (!boundary) {
                    continue;
                }
                for (int c = std::max(0, k - reach); c <= std::min(d.z - 1, k + reach); ++c) {
                    for (int b = std::max(0, j - reach); b <= std::min(d.y - 1, j + reach); ++b) {
                        for (int a = std::max(0, i - reach); a <= std::min(d.x - 1, i + reach);
                             ++a) {
                            if (label(a, b, c) == in) {
                                continue;
                            }
                            const float dist =
                                std::sqrt(static_cast<float>((a - i) * (a - i) + (b - j) * (b - j) +
                                                             (c - k) * (c - k))) -
                                0.5F;
                            float& m = magnitude[linearIndex(d, a, b, c)];
                            m = std::min(m, dist);
                        }
                    }
                }
            }
        }
    }
    std::vector<float> phi(mask.size());
    for (std::size_t n = 0; n < mask.size(); ++n) {
        phi[n] = mask[n] != 0 ? -magnitude[n] : magnitude[n];
    }
    return phi;
}

std::vector<float> smoothMaskPhi(std::span<const std::uint8_t> mask, const glm::ivec3& d) {
    std::vector<float> phi = maskToPhi(mask, d);
    std::vector<float> next(phi.size());
    const std::array<std::size_t, 3> stride{1, static_cast<std::size_t>(d.x),
                                            static_cast<std::size_t>(d.x) * d.y};
    for (int pass = 0; pass < 2; ++pass) {
        for (int axis = 0; axis < 3; ++axis) {
            const int n = d[axis];
            for (int k = 0; k < d.z; ++k) {
                for (int j = 0; j < d.y; ++j) {
                    for (int i = 0; i < d.x; ++i) {
                        const int at = glm::ivec3(i, j, k)[axis];
                        const std::size_t c = linearIndex(d, i, j, k);
                        // The volume's faces repeat their voxel.
                        const float lo = at > 0 ? phi[c - stride[axis]] : phi[c];
                        const float hi = at + 1 < n ? phi[c + stride[axis]] : phi[c];
                        next[c] = 0.25F * lo + 0.5F * phi[c] + 0.25F * hi;
                    }
                }
            }
            phi.swap(next);
        }
    }
    constexpr float kSide = 0.05F;
    for (std::size_t n = 0; n < phi.size(); ++n) {
        phi[n] = mask[n] != 0 ? std::min(phi[n], -kSide) : std::max(phi[n], kSide);
    }
    return phi;
}

std::vector<std::uint8_t> thresholdMask(std::span<const float> values, float lo, float hi) {
    if (std::isnan(lo) || std::isnan(hi) || lo > hi) {
        throw std::invalid_argument("threshold range [" + std::to_string(lo) + ", " +
                                    std::to_string(hi) + "] is empty");
    }
    std::vector<std::uint8_t> mask(values.size());
    std::transform(values.begin(), values.end(), mask.begin(),
                   [&](float v) { return static_cast<std::uint8_t>(v >= lo && v <= hi); });
    return mask;
}

void applySphere(std::vector<float>& phi, const glm::ivec3& d, const model::Sphere& s, bool add) {
    for (int k = 0; k < d.z; ++k) {
        for (int j = 0; j < d.y; ++j) {
            for (int i = 0; i < d.x; ++i) {
                const float sd = model::sphereDistance(s, glm::vec3(i, j, k));
                float& p = phi[linearIndex(d, i, j, k)];
                p = clampPhi(add ? std::min(p, sd) : std::max(p, -sd));
            }
        }
    }
}

std::vector<std::uint8_t> insideMask(std::span<const float> phi) {
    std::vector<std::uint8_t> mask(phi.size());
    std::transform(phi.begin(), phi.end(), mask.begin(),
                   [](float p) { return static_cast<std::uint8_t>(p < 0.0F); });
    return mask;
}

} // namespace steerseg::solver
