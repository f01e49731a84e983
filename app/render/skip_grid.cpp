#include "render/skip_grid.hpp"

#include "gpu/gl_error.hpp"
#include "gpu/gl_state_guard.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace steerseg::render {

namespace {

// Fills `out` with the ranges of every block of block layer bz (kSkipRangeChannels floats a
// block). `at(i, j, k)` gives a value; only slices 8 bz - 3 .. 8 bz + 10 are asked for (the
// apron and the gradient's two neighbours either side).
template <typename At>
void layerRanges(const glm::ivec3& dims, const glm::ivec3& grid, int bz, const At& at,
                 std::vector<float>& out) {
    const auto clamped = [&](int i, int j, int k) {
        return at(std::clamp(i, 0, dims.x - 1), std::clamp(j, 0, dims.y - 1),
                  std::clamp(k, 0, dims.z - 1));
    };
    for (int by = 0; by < grid.y; ++by) {
        for (int bx = 0; bx < grid.x; ++bx) {
            const glm::ivec3 lo = glm::max(glm::ivec3(bx, by, bz) * kSkipBlock - 1, 0);
            const glm::ivec3 hi =
                glm::min(glm::ivec3(bx, by, bz) * kSkipBlock + kSkipBlock + 1, dims);
            float mn = std::numeric_limits<float>::max();
            float mx = std::numeric_limits<float>::lowest();
            float gradient2 = 0.0F;
            for (int k = lo.z; k < hi.z; ++k) {
                for (int j = lo.y; j < hi.y; ++j) {
                    for (int i = lo.x; i < hi.x; ++i) {
                        const float v = at(i, j, k);
                        mn = std::min(mn, v);
                        mx = std::max(mx, v);
                        // The ray caster's gradient (render/gradient.comp): the difference
                        // [-1 -2 0 2 1] / 8 along each axis, with the edge clamped.
                        const auto along = [&](const glm::ivec3& e) {
                            const glm::ivec3 p(i, j, k);
                            const auto f = [&](const glm::ivec3& q) {
                                return clamped(q.x, q.y, q.z);
                            };
                            return (2.0F * (f(p + e) - f(p - e)) + f(p + 2 * e) - f(p - 2 * e)) /
                                   8.0F;
                        };
                        const float gx = along({1, 0, 0});
                        const float gy = along({0, 1, 0});
                        const float gz = along({0, 0, 1});
                        gradient2 = std::max(gradient2, gx * gx + gy * gy + gz * gz);
                    }
                }
            }
            const std::size_t cell =
                static_cast<std::size_t>(bx) +
                static_cast<std::size_t>(grid.x) *
                    (static_cast<std::size_t>(by) +
                     static_cast<std::size_t>(grid.y) * static_cast<std::size_t>(bz));
            float* range = &out[kSkipRangeChannels * cell];
            range[0] = mn;
            range[1] = mx;
            range[2] = 0.0F;
            range[3] = std::sqrt(gradient2);
        }
    }
}

} // namespace

std::vector<float> blockRanges(const std::vector<float>& values, const glm::ivec3& dims) {
    const glm::ivec3 grid = (dims + kSkipBlock - 1) / kSkipBlock;
    std::vector<float> out(static_cast<std::size_t>(grid.x) * grid.y * grid.z * kSkipRangeChannels);
    const auto at = [&](int i, int j, int k) { return values[linearIndex(dims, i, j, k)]; };
    for (int bz = 0; bz < grid.z; ++bz) {
        layerRanges(dims, grid, bz, at, out);
    }
    return out;
}

SkipGrid::SkipGrid(const Volume& volume, const gpu::ScanTexture& scan)
    : dims_((volume.dims() + kSkipBlock - 1) / kSkipBlock) {
    const glm::ivec3 d = volume.dims();
    const std::size_t slice = static_cast<std::size_t>(d.x) * static_cast<std::size_t>(d.y);
    std::vector<float> out(static_cast<std::size_t>(dims_.x) * dims_.y * dims_.z *
                           kSkipRangeChannels);
    std::vector<float> slab;
    for (int bz = 0; bz < dims_.z; ++bz) {
        const int k0 = std::max(bz * kSkipBlock - 3, 0);
        const int k1 = std::min(bz * kSkipBlock + kSkipBlock + 3, d.z);
        slab.resize(slice * static_cast<std::size_t>(k1 - k0));
        volume.realValues(slice * static_cast<std::size_t>(k0), slab);
        for (float& v : slab) {
            v = static_cast<float>(scan.normalise(static_cast<double>(v)));
        }
        const auto at = [&](int i, int j, int k) { return slab[linearIndex(d, i, j, k - k0)]; };
        layerRanges(d, dims_, bz, at, out);
    }
    gpu::GlStateGuard guard;
    glActiveTexture(GL_TEXTURE0);
    glBindBuffer(GL_PIXEL_UNPACK_BUFFER, 0);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
    texture_ = gpu::createTexture();
    glBindTexture(GL_TEXTURE_3D, texture_.id());
    glTexStorage3D(GL_TEXTURE_3D, 1, GL_RGBA16F, dims_.x, dims_.y, dims_.z);
    glTexSubImage3D(GL_TEXTURE_3D, 0, 0, 0, 0, dims_.x, dims_.y, dims_.z, GL_RGBA, GL_FLOAT,
                    out.data());
    glTexParameteri(GL_TEXTURE_3D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_3D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    gpu::checkGl("uploading the skipping grid");
}

} // namespace steerseg::render
