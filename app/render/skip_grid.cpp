#include "render/skip_grid.hpp"

#include "render/transfer_function.hpp"

#include <algorithm>
#include <cmath>

namespace steerseg::render {

namespace {

constexpr int kBinsPerBand = kTfIntensityBins / kSkipBands;
static_assert(kBinsPerBand * kSkipBands == kTfIntensityBins);

// The transfer-function bins a sample between lo and hi (normalised intensity) may touch: the
// LUT is filtered between neighbouring bins. The margin covers the half-float display texture
// where floats do not filter (an eighth of a bin at most) and the GPU's float arithmetic.
constexpr float kBinMargin = 0.25F;

int binBelow(float v) {
    return std::clamp(static_cast<int>(std::floor(v * (kTfIntensityBins - 1) - kBinMargin)), 0,
                      kTfIntensityBins - 1);
}

int binAbove(float v) {
    return std::clamp(static_cast<int>(std::ceil(v * (kTfIntensityBins - 1) + kBinMargin)), 0,
                      kTfIntensityBins - 1);
}

// Fills the bands of every block of block layer bz. `at(i, j, k)` gives a value; only slices
// block bz - 3 .. block (bz + 1) + 2 are asked for (the cells' corners and the gradient's two
// neighbours either side).
template <typename At>
void layerBands(const glm::ivec3& dims, int block, const glm::ivec3& grid, int bz, const At& at,
                std::vector<float>& out) {
    const auto clampedAt = [&](int i, int j, int k) {
        return at(std::clamp(i, 0, dims.x - 1), std::clamp(j, 0, dims.y - 1),
                  std::clamp(k, 0, dims.z - 1));
    };
    // The samples of block b lie in [block b - 0.5, block (b + 1) - 0.5): cells block b - 1 ..
    // block (b + 1) - 1, whose corners clamp to the volume (cell -1 is voxel 0's own, inside
    // cell 0's range).
    const int cellK0 = std::clamp(bz * block - 1, 0, dims.z - 1);
    const int cellK1 = std::clamp(bz * block + block - 1, 0, dims.z - 1);
    const int cornerK1 = std::min(cellK1 + 1, dims.z - 1);
    const int slices = cornerK1 - cellK0 + 1;
    const std::size_t slice = static_cast<std::size_t>(dims.x) * static_cast<std::size_t>(dims.y);
    const auto local = [&](int i, int j, int k) {
        return static_cast<std::size_t>(i) +
               static_cast<std::size_t>(dims.x) *
                   (static_cast<std::size_t>(j) +
                    static_cast<std::size_t>(dims.y) * static_cast<std::size_t>(k - cellK0));
    };
    // Per corner voxel: its intensity and the ray caster's gradient magnitude
    // (render/gradient.comp: [-1 -2 0 2 1] / 8 along each axis, the edge clamped). Then per
    // cell (its corners at +0 / +1 per axis, clamped), separably: the min and max intensity and
    // the largest gradient.
    std::vector<float> lo(slice * static_cast<std::size_t>(slices));
    std::vector<float> hi(lo.size());
    std::vector<float> grad(lo.size());
    for (int k = cellK0; k <= cornerK1; ++k) {
        for (int j = 0; j < dims.y; ++j) {
            for (int i = 0; i < dims.x; ++i) {
                const auto along = [&](int di, int dj, int dk) {
                    return (2.0F * (clampedAt(i + di, j + dj, k + dk) -
                                    clampedAt(i - di, j - dj, k - dk)) +
                            clampedAt(i + 2 * di, j + 2 * dj, k + 2 * dk) -
                            clampedAt(i - 2 * di, j - 2 * dj, k - 2 * dk)) /
                           8.0F;
                };
                const float gx = along(1, 0, 0);
                const float gy = along(0, 1, 0);
                const float gz = along(0, 0, 1);
                const std::size_t n = local(i, j, k);
                lo[n] = hi[n] = at(i, j, k);
                grad[n] = std::sqrt(gx * gx + gy * gy + gz * gz);
            }
        }
    }
    const auto pairWith = [&](std::size_t n, std::size_t m) {
        lo[n] = std::min(lo[n], lo[m]);
        hi[n] = std::max(hi[n], hi[m]);
        grad[n] = std::max(grad[n], grad[m]);
    };
    for (int k = cellK0; k <= cornerK1; ++k) {
        for (int j = 0; j < dims.y; ++j) {
            for (int i = 0; i + 1 < dims.x; ++i) {
                pairWith(local(i, j, k), local(i + 1, j, k));
            }
        }
        for (int j = 0; j + 1 < dims.y; ++j) {
            for (int i = 0; i < dims.x; ++i) {
                pairWith(local(i, j, k), local(i, j + 1, k));
            }
        }
    }
    for (int k = cellK0; k <= cellK1 && k < cornerK1; ++k) {
        for (int j = 0; j < dims.y; ++j) {
            for (int i = 0; i < dims.x; ++i) {
                pairWith(local(i, j, k), local(i, j, k + 1));
            }
        }
    }
    // Each cell's bands, once: a cell lies in up to eight blocks' aprons.
    std::vector<std::uint8_t> bandLo(lo.size());
    std::vector<std::uint8_t> bandHi(lo.size());
    for (std::size_t n = 0; n < lo.size(); ++n) {
        bandLo[n] = static_cast<std::uint8_t>(binBelow(lo[n]) / kBinsPerBand);
        bandHi[n] = static_cast<std::uint8_t>(binAbove(hi[n]) / kBinsPerBand);
    }
    for (int by = 0; by < grid.y; ++by) {
        for (int bx = 0; bx < grid.x; ++bx) {
            const std::size_t cell =
                static_cast<std::size_t>(bx) +
                static_cast<std::size_t>(grid.x) *
                    (static_cast<std::size_t>(by) +
                     static_cast<std::size_t>(grid.y) * static_cast<std::size_t>(bz));
            float* bands = &out[kSkipBands * cell];
            std::fill(bands, bands + kSkipBands, -1.0F);
            const int i0 = std::max(bx * block - 1, 0);
            const int i1 = std::min(bx * block + block - 1, dims.x - 1);
            const int j0 = std::max(by * block - 1, 0);
            const int j1 = std::min(by * block + block - 1, dims.y - 1);
            for (int k = cellK0; k <= cellK1; ++k) {
                for (int j = j0; j <= j1; ++j) {
                    for (int i = i0; i <= i1; ++i) {
                        const std::size_t n = local(i, j, k);
                        for (int b = bandLo[n]; b <= bandHi[n]; ++b) {
                            bands[b] = std::max(bands[b], grad[n]);
                        }
                    }
                }
            }
        }
    }
}

} // namespace

std::vector<float> blockBands(const std::vector<float>& values, const glm::ivec3& dims, int block) {
    const glm::ivec3 grid = (dims + block - 1) / block;
    std::vector<float> out(static_cast<std::size_t>(grid.x) * grid.y * grid.z * kSkipBands);
    const auto at = [&](int i, int j, int k) { return values[linearIndex(dims, i, j, k)]; };
    for (int bz = 0; bz < grid.z; ++bz) {
        layerBands(dims, block, grid, bz, at, out);
    }
    return out;
}

bool bandsVisible(const float* bands, const std::vector<float>& occupancy, double gradientScale) {
    for (int b = 0; b < kSkipBands; ++b) {
        if (bands[b] < 0.0F) {
            continue;
        }
        // The ray caster's gradient bins up to this largest gradient, + 1 for the gradient
        // texture's half-float rounding.
        const int gHi =
            std::clamp(static_cast<int>(std::ceil(static_cast<double>(bands[b]) / gradientScale *
                                                  (kTfGradientBins - 1))) +
                           1,
                       0, kTfGradientBins - 1);
        if (occupiedIn(occupancy, b * kBinsPerBand, b * kBinsPerBand + kBinsPerBand - 1, gHi)) {
            return true;
        }
    }
    return false;
}

SkipGrid::SkipGrid(const Volume& volume, const gpu::ScanTexture& scan, std::size_t budget) {
    const glm::ivec3 d = volume.dims();
    const auto blocksOf = [&](int block) {
        const glm::ivec3 grid = (d + block - 1) / block;
        return static_cast<std::size_t>(grid.x) * static_cast<std::size_t>(grid.y) *
               static_cast<std::size_t>(grid.z);
    };
    for (const int block : {2, 4}) {
        if (blocksOf(block) * kSkipBands * sizeof(float) <= budget) {
            block_ = block;
            break;
        }
    }
    dims_ = (d + block_ - 1) / block_;
    const std::size_t slice = static_cast<std::size_t>(d.x) * static_cast<std::size_t>(d.y);
    bands_.resize(blocksOf(block_) * kSkipBands);
    std::vector<float> slab;
    for (int bz = 0; bz < dims_.z; ++bz) {
        const int k0 = std::max(bz * block_ - 3, 0);
        const int k1 = std::min(bz * block_ + block_ + 3, d.z);
        slab.resize(slice * static_cast<std::size_t>(k1 - k0));
        volume.realValues(slice * static_cast<std::size_t>(k0), slab);
        for (float& v : slab) {
            v = static_cast<float>(scan.normalise(static_cast<double>(v)));
        }
        const auto at = [&](int i, int j, int k) { return slab[linearIndex(d, i, j, k - k0)]; };
        layerBands(d, block_, dims_, bz, at, bands_);
    }
}

std::vector<std::uint8_t> SkipGrid::visibleBlocks(const std::vector<float>& occupancy,
                                                  double gradientScale) const {
    std::vector<std::uint8_t> visible(bands_.size() / kSkipBands);
    for (std::size_t b = 0; b < visible.size(); ++b) {
        visible[b] = bandsVisible(&bands_[b * kSkipBands], occupancy, gradientScale) ? 1 : 0;
    }
    return visible;
}

std::vector<std::uint8_t> labelledBlocks(std::span<const std::uint8_t> labels,
                                         const glm::ivec3& dims, int block) {
    const glm::ivec3 grid = (dims + block - 1) / block;
    std::vector<std::uint8_t> out(static_cast<std::size_t>(grid.x) *
                                  static_cast<std::size_t>(grid.y) *
                                  static_cast<std::size_t>(grid.z));
    std::size_t v = 0;
    for (int k = 0; k < dims.z; ++k) {
        for (int j = 0; j < dims.y; ++j) {
            const std::size_t row =
                static_cast<std::size_t>(grid.x) *
                (static_cast<std::size_t>(j / block) +
                 static_cast<std::size_t>(grid.y) * static_cast<std::size_t>(k / block));
            for (int i = 0; i < dims.x; ++i, ++v) {
                if (labels[v] != 0) {
                    out[row + static_cast<std::size_t>(i / block)] = 1;
                }
            }
        }
    }
    return out;
}

} // namespace steerseg::render
