#include "gpu/scan_texture.hpp"

#include "gpu/gl_error.hpp"
#include "gpu/gl_state_guard.hpp"
#include "gpu/gpu_info.hpp"
#include "gpu/gpu_limits.hpp"

#include <algorithm>
#include <stdexcept>
#include <string>
#include <vector>

namespace steerseg::gpu {

namespace {

// Slices per upload: about 8 MiB of floats at a time, at least one slice.
int slabSlices(const glm::ivec3& dims) {
    const std::size_t slice = static_cast<std::size_t>(dims.x) * static_cast<std::size_t>(dims.y);
    return static_cast<int>(std::clamp<std::size_t>((std::size_t{8} << 20) / (4 * slice), 1,
                                                    static_cast<std::size_t>(dims.z)));
}

void checkSize(const glm::ivec3& dims) {
    if (dims.x <= 0 || dims.y <= 0 || dims.z <= 0) {
        throw std::invalid_argument("scan texture: empty volume");
    }
    const int limit = gpuLimits().max3dTextureSize;
    if (std::max({dims.x, dims.y, dims.z}) > limit) {
        throw GpuCapacityError("scan " + sizeText(dims.x, dims.y, dims.z) +
                               " exceeds GL_MAX_3D_TEXTURE_SIZE " + std::to_string(limit) +
                               " of this GPU");
    }
}

double voxelCount(const glm::ivec3& dims) {
    return static_cast<double>(dims.x) * static_cast<double>(dims.y) * static_cast<double>(dims.z);
}

Texture allocate(GLenum format, const glm::ivec3& dims, GLenum filter) {
    Texture t = createTexture();
    glBindTexture(GL_TEXTURE_3D, t.id());
    glTexStorage3D(GL_TEXTURE_3D, 1, format, dims.x, dims.y, dims.z);
    glTexParameteri(GL_TEXTURE_3D, GL_TEXTURE_MIN_FILTER, static_cast<GLint>(filter));
    glTexParameteri(GL_TEXTURE_3D, GL_TEXTURE_MAG_FILTER, static_cast<GLint>(filter));
    for (GLenum wrap : {GL_TEXTURE_WRAP_S, GL_TEXTURE_WRAP_T, GL_TEXTURE_WRAP_R}) {
        glTexParameteri(GL_TEXTURE_3D, wrap, GL_CLAMP_TO_EDGE);
    }
    return t;
}

} // namespace

ScanTexture::ScanTexture(const Volume& volume, ScanDisplay display)
    : dims_(volume.dims()), spacing_(volume.geometry().spacing) {
    checkSize(dims_);
    const IntensityStats& stats = volume.stats();
    min_ = stats.min;
    max_ = stats.max > stats.min ? stats.max : stats.min + 1.0;
    const std::size_t slice = static_cast<std::size_t>(dims_.x) * static_cast<std::size_t>(dims_.y);
    upload(
        [&](int k0, int count, std::vector<float>& out) {
            out.resize(slice * static_cast<std::size_t>(count));
            volume.realValues(slice * static_cast<std::size_t>(k0), out);
        },
        display);
}

ScanTexture::ScanTexture(std::span<const float> intensities, const glm::ivec3& dims) : dims_(dims) {
    checkSize(dims_);
    const std::size_t slice = static_cast<std::size_t>(dims.x) * static_cast<std::size_t>(dims.y);
    if (intensities.size() != slice * static_cast<std::size_t>(dims.z)) {
        throw std::invalid_argument("scan texture: intensities do not match the dimensions");
    }
    const auto [lo, hi] = std::minmax_element(intensities.begin(), intensities.end());
    min_ = static_cast<double>(*lo);
    max_ = *hi > *lo ? static_cast<double>(*hi) : static_cast<double>(*lo) + 1.0;
    upload(
        [&](int k0, int count, std::vector<float>& out) {
            const auto first = intensities.begin() + static_cast<std::ptrdiff_t>(slice * k0);
            out.assign(first, first + static_cast<std::ptrdiff_t>(slice * count));
        },
        ScanDisplay::Auto);
}

// `slices(k0, count, out)` fills `out` with real-unit values of slices k0..k0+count-1.
template <typename SliceSource>
void ScanTexture::upload(const SliceSource& slices, ScanDisplay display) {
    GlStateGuard guard;
    glActiveTexture(GL_TEXTURE0);
    glBindBuffer(GL_PIXEL_UNPACK_BUFFER, 0);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
    const bool filterFloats = queryGpuInfo().floatLinearFiltering;
    exact_ = allocate(GL_R32F, dims_, filterFloats ? GL_LINEAR : GL_NEAREST);
    if (!filterFloats || display == ScanDisplay::HalfFloatCopy) {
        display_ = allocate(GL_R16F, dims_, GL_LINEAR);
    }
    // Drivers report a texture larger than their memory here, not at the first upload.
    const GLenum error = glGetError();
    if (error == GL_OUT_OF_MEMORY) {
        throw GpuCapacityError("scan " + sizeText(dims_.x, dims_.y, dims_.z) + " (" +
                               bytesText(voxelCount(dims_) * (display_ ? 6.0 : 4.0)) + " as R32F" +
                               (display_ ? " + R16F" : "") +
                               ") does not fit in this GPU's memory (GL_OUT_OF_MEMORY)");
    }
    if (error != GL_NO_ERROR) {
        throw GlError("allocating the scan texture: " + glErrorName(error));
    }
    const int slab = slabSlices(dims_);
    std::vector<float> values;
    for (int k0 = 0; k0 < dims_.z; k0 += slab) {
        const int count = std::min(slab, dims_.z - k0);
        slices(k0, count, values);
        glBindTexture(GL_TEXTURE_3D, exact_.id());
        glTexSubImage3D(GL_TEXTURE_3D, 0, 0, 0, k0, dims_.x, dims_.y, count, GL_RED, GL_FLOAT,
                        values.data());
        if (display_) {
            for (float& v : values) {
                v = static_cast<float>(normalise(static_cast<double>(v)));
            }
            glBindTexture(GL_TEXTURE_3D, display_.id());
            glTexSubImage3D(GL_TEXTURE_3D, 0, 0, 0, k0, dims_.x, dims_.y, count, GL_RED, GL_FLOAT,
                            values.data());
        }
    }
    gpu::checkGl("uploading the scan texture");
}

glm::vec2 ScanTexture::toNormalised() const {
    if (display_) {
        return {1.0F, 0.0F};
    }
    return {static_cast<float>(1.0 / (max_ - min_)), static_cast<float>(-min_ / (max_ - min_))};
}

double ScanTexture::normalise(double real) const {
    return (real - min_) / (max_ - min_);
}

} // namespace steerseg::gpu
