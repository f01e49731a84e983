#include "core/volume.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>
#include <stdexcept>

namespace steerseg {

std::size_t voxelBytes(VoxelType type) {
    switch (type) {
    case VoxelType::UInt8:
        return 1;
    case VoxelType::Int16:
    case VoxelType::UInt16:
        return 2;
    case VoxelType::Float32:
        return 4;
    }
    return 1;
}

std::string dimsText(const glm::ivec3& dims) {
    return std::to_string(dims.x) + "x" + std::to_string(dims.y) + "x" + std::to_string(dims.z);
}

const char* voxelTypeName(VoxelType type) {
    switch (type) {
    case VoxelType::UInt8:
        return "uint8";
    case VoxelType::Int16:
        return "int16";
    case VoxelType::UInt16:
        return "uint16";
    case VoxelType::Float32:
        return "float32";
    }
    return "unknown";
}

std::size_t Geometry::voxelCount() const {
    if (dims.x <= 0 || dims.y <= 0 || dims.z <= 0) {
        return 0;
    }
    return static_cast<std::size_t>(dims.x) * static_cast<std::size_t>(dims.y) *
           static_cast<std::size_t>(dims.z);
}

glm::dvec3 Geometry::indexToWorld(const glm::dvec3& index) const {
    return origin + direction * (spacing * index);
}

glm::dvec3 Geometry::worldToIndex(const glm::dvec3& world) const {
    return (glm::inverse(direction) * (world - origin)) / spacing;
}

std::array<double, 9> Geometry::directionRowMajor() const {
    std::array<double, 9> out{};
    for (int r = 0; r < 3; ++r) {
        for (int c = 0; c < 3; ++c) {
            out[static_cast<std::size_t>(r * 3 + c)] = direction[c][r]; // glm is column-major
        }
    }
    return out;
}

Volume::Volume(VoxelType type, const Geometry& geometry) : type_(type), geometry_(geometry) {
    if (geometry.voxelCount() == 0) {
        throw std::invalid_argument("volume dimensions must be positive");
    }
    data_.resize(geometry.voxelCount() * voxelBytes(type));
}

double Volume::storedAt(std::size_t linear) const {
    switch (type_) {
    case VoxelType::UInt8:
        return static_cast<double>(voxels<std::uint8_t>()[linear]);
    case VoxelType::Int16:
        return static_cast<double>(voxels<std::int16_t>()[linear]);
    case VoxelType::UInt16:
        return static_cast<double>(voxels<std::uint16_t>()[linear]);
    case VoxelType::Float32:
        return static_cast<double>(voxels<float>()[linear]);
    }
    return 0.0;
}

std::string rescaleProblem(const Rescale& rescale, double storedMin, double storedMax) {
    const auto text = [](double v) {
        std::ostringstream s;
        s << v;
        return s.str();
    };
    if (!std::isfinite(rescale.slope)) {
        return "slope is " + text(rescale.slope);
    }
    if (!std::isfinite(rescale.intercept)) {
        return "intercept is " + text(rescale.intercept);
    }
    // The map is linear: its extremes are at the ends of the stored range.
    for (const double stored : {storedMin, storedMax}) {
        const double real = rescale.apply(stored);
        if (!std::isfinite(real) ||
            std::abs(real) > static_cast<double>(std::numeric_limits<float>::max())) {
            return "slope " + text(rescale.slope) + " and intercept " + text(rescale.intercept) +
                   " take stored " + text(stored) + " to " + text(real) +
                   ", beyond float32's range";
        }
    }
    return {};
}

std::pair<double, double> Volume::storedRange() const {
    const auto range = [](auto v) -> std::pair<double, double> {
        if (v.empty()) {
            return {0.0, 0.0};
        }
        const auto [lo, hi] = std::minmax_element(v.begin(), v.end());
        return {static_cast<double>(*lo), static_cast<double>(*hi)};
    };
    switch (type_) {
    case VoxelType::UInt8:
        return range(voxels<std::uint8_t>());
    case VoxelType::Int16:
        return range(voxels<std::int16_t>());
    case VoxelType::UInt16:
        return range(voxels<std::uint16_t>());
    case VoxelType::Float32:
        return range(voxels<float>());
    }
    return {0.0, 0.0};
}

namespace {

template <typename T> IntensityStats computeStats(std::span<const T> v, const Rescale& r) {
    IntensityStats s;
    s.histogram.assign(kHistogramBins, 0);
    if (v.empty()) {
        return s;
    }
    double lo = std::numeric_limits<double>::infinity();
    double hi = -lo;
    double sum = 0.0;
    for (T x : v) {
        const auto d = static_cast<double>(x);
        lo = std::min(lo, d);
        hi = std::max(hi, d);
        sum += d;
    }
    const double meanStored = sum / static_cast<double>(v.size());
    // Stored range maps to the real range; a negative slope swaps ends.
    const double a = r.apply(lo);
    const double b = r.apply(hi);
    s.min = std::min(a, b);
    s.max = std::max(a, b);
    s.mean = r.apply(meanStored);
    const double width = hi - lo;
    for (T x : v) {
        const double realBin = width > 0.0 ? (static_cast<double>(x) - lo) / width : 0.0;
        auto bin = static_cast<int>(realBin * kHistogramBins);
        bin = std::clamp(bin, 0, kHistogramBins - 1);
        if (r.slope < 0.0) {
            bin = kHistogramBins - 1 - bin;
        }
        ++s.histogram[static_cast<std::size_t>(bin)];
    }
    return s;
}

} // namespace

const IntensityStats& Volume::stats() const {
    if (!stats_) {
        IntensityStats s;
        switch (type_) {
        case VoxelType::UInt8:
            s = computeStats(voxels<std::uint8_t>(), rescale_);
            break;
        case VoxelType::Int16:
            s = computeStats(voxels<std::int16_t>(), rescale_);
            break;
        case VoxelType::UInt16:
            s = computeStats(voxels<std::uint16_t>(), rescale_);
            break;
        case VoxelType::Float32:
            s = computeStats(voxels<float>(), rescale_);
            break;
        }
        stats_ = std::make_shared<const IntensityStats>(std::move(s));
    }
    return *stats_;
}

std::vector<float> Volume::realValues() const {
    std::vector<float> out(geometry_.voxelCount());
    realValues(0, out);
    return out;
}

void Volume::realValues(std::size_t first, std::span<float> out) const {
    if (first > geometry_.voxelCount() || out.size() > geometry_.voxelCount() - first) {
        throw std::out_of_range("Volume::realValues: range past the last voxel");
    }
    for (std::size_t n = 0; n < out.size(); ++n) {
        out[n] = static_cast<float>(realAt(first + n));
    }
}

} // namespace steerseg
