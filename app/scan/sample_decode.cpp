#include "scan/sample_decode.hpp"

#include "scan/byte_source.hpp"
#include "scan/load_checks.hpp"

#include <algorithm>
#include <bit>
#include <charconv>
#include <cmath>
#include <cstring>
#include <limits>
#include <type_traits>

namespace steerseg::scan {

std::size_t sampleBytes(SampleType type) {
    switch (type) {
    case SampleType::Int8:
    case SampleType::UInt8:
        return 1;
    case SampleType::Int16:
    case SampleType::UInt16:
        return 2;
    case SampleType::Int32:
    case SampleType::UInt32:
    case SampleType::Float32:
        return 4;
    case SampleType::Int64:
    case SampleType::UInt64:
    case SampleType::Float64:
        return 8;
    }
    return 1;
}

const char* sampleTypeName(SampleType type) {
    constexpr const char* names[] = {"int8",   "uint8", "int16",  "uint16",  "int32",
                                     "uint32", "int64", "uint64", "float32", "float64"};
    return names[static_cast<std::size_t>(type)];
}

VoxelType storedTypeFor(SampleType type) {
    switch (type) {
    case SampleType::UInt8:
        return VoxelType::UInt8;
    case SampleType::Int8:
    case SampleType::Int16:
        return VoxelType::Int16;
    case SampleType::UInt16:
        return VoxelType::UInt16;
    default:
        return VoxelType::Float32;
    }
}

std::string expectedDataText(const char* who, const glm::ivec3& dims, SampleType type) {
    const auto bytes = static_cast<std::uint64_t>(dims.x) * static_cast<std::uint64_t>(dims.y) *
                       static_cast<std::uint64_t>(dims.z) * sampleBytes(type);
    return std::string(who) + " says " + dimsText(dims) + " " + sampleTypeName(type) + " (" +
           sizeText(bytes) + ")";
}

namespace {

template <typename T> T loadSample(const std::byte* p, bool swap) {
    std::array<std::byte, sizeof(T)> b{};
    std::memcpy(b.data(), p, sizeof(T));
    if (swap) {
        std::reverse(b.begin(), b.end());
    }
    return std::bit_cast<T>(b);
}

template <typename In, typename Out>
void convertAll(std::span<const std::byte> raw, std::span<Out> out, bool swap) {
    for (std::size_t n = 0; n < out.size(); ++n) {
        out[n] = static_cast<Out>(loadSample<In>(raw.data() + n * sizeof(In), swap));
    }
}

template <typename Out>
void convertTo(SampleType type, std::span<const std::byte> raw, std::span<Out> out, bool swap) {
    switch (type) {
    case SampleType::Int8:
        return convertAll<std::int8_t>(raw, out, swap);
    case SampleType::UInt8:
        return convertAll<std::uint8_t>(raw, out, swap);
    case SampleType::Int16:
        return convertAll<std::int16_t>(raw, out, swap);
    case SampleType::UInt16:
        return convertAll<std::uint16_t>(raw, out, swap);
    case SampleType::Int32:
        return convertAll<std::int32_t>(raw, out, swap);
    case SampleType::UInt32:
        return convertAll<std::uint32_t>(raw, out, swap);
    case SampleType::Int64:
        return convertAll<std::int64_t>(raw, out, swap);
    case SampleType::UInt64:
        return convertAll<std::uint64_t>(raw, out, swap);
    case SampleType::Float32:
        return convertAll<float>(raw, out, swap);
    case SampleType::Float64:
        // Values past float's range become infinite and are refused by checkFinite.
        for (std::size_t n = 0; n < out.size(); ++n) {
            const double v = loadSample<double>(raw.data() + n * 8, swap);
            const auto limit = static_cast<double>(std::numeric_limits<float>::max());
            out[n] = std::abs(v) <= limit || std::isnan(v)
                         ? static_cast<Out>(v)
                         : static_cast<Out>(v > 0 ? std::numeric_limits<float>::infinity()
                                                  : -std::numeric_limits<float>::infinity());
        }
        return;
    }
}

} // namespace

Volume decodeVolume(const std::filesystem::path& path, const Geometry& geometry, SampleType type,
                    ByteOrder order, std::span<const std::byte> raw) {
    Volume volume(storedTypeFor(type), geometry);
    const std::size_t count = geometry.voxelCount();
    if (raw.size() != count * sampleBytes(type)) {
        throw ScanError(path, "internal error: sample buffer size does not match the dimensions");
    }
    const bool swap = sampleBytes(type) > 1 &&
                      (order == ByteOrder::Big) != (std::endian::native == std::endian::big);
    switch (volume.type()) {
    case VoxelType::UInt8:
        convertTo(type, raw, volume.voxels<std::uint8_t>(), swap);
        break;
    case VoxelType::Int16:
        convertTo(type, raw, volume.voxels<std::int16_t>(), swap);
        break;
    case VoxelType::UInt16:
        convertTo(type, raw, volume.voxels<std::uint16_t>(), swap);
        break;
    case VoxelType::Float32:
        convertTo(type, raw, volume.voxels<float>(), swap);
        break;
    }
    checkFinite(path, volume);
    return volume;
}

namespace {

template <typename T> bool storeParsed(double v, std::byte* dst) {
    T value{};
    if constexpr (std::is_floating_point_v<T>) {
        // Out-of-range values become infinite (refused later), never an undefined conversion.
        const auto limit = static_cast<double>(std::numeric_limits<T>::max());
        value = std::abs(v) <= limit || std::isnan(v)
                    ? static_cast<T>(v)
                    : (v > 0 ? std::numeric_limits<T>::infinity()
                             : -std::numeric_limits<T>::infinity());
    } else {
        // Exact bounds: [lowest, 2^digits), so the truncating conversion is always defined.
        const double upper = std::ldexp(1.0, std::numeric_limits<T>::digits);
        const double lower = static_cast<double>(std::numeric_limits<T>::lowest()) - 1.0;
        if (!(v > lower && v < upper)) {
            return false;
        }
        value = static_cast<T>(v);
    }
    std::memcpy(dst, &value, sizeof(T));
    return true;
}

bool storeAs(SampleType type, double v, std::byte* dst) {
    switch (type) {
    case SampleType::Int8:
        return storeParsed<std::int8_t>(v, dst);
    case SampleType::UInt8:
        return storeParsed<std::uint8_t>(v, dst);
    case SampleType::Int16:
        return storeParsed<std::int16_t>(v, dst);
    case SampleType::UInt16:
        return storeParsed<std::uint16_t>(v, dst);
    case SampleType::Int32:
        return storeParsed<std::int32_t>(v, dst);
    case SampleType::UInt32:
        return storeParsed<std::uint32_t>(v, dst);
    case SampleType::Int64:
        return storeParsed<std::int64_t>(v, dst);
    case SampleType::UInt64:
        return storeParsed<std::uint64_t>(v, dst);
    case SampleType::Float32:
        return storeParsed<float>(v, dst);
    case SampleType::Float64:
        return storeParsed<double>(v, dst);
    }
    return false;
}

} // namespace

Volume decodeAsciiVolume(const std::filesystem::path& path, const Geometry& geometry,
                         SampleType type, std::string_view text) {
    const std::size_t count = geometry.voxelCount();
    // Each number takes at least two characters with its separator, so the text bounds the size.
    if (count > text.size() / 2 + 1) {
        throw ScanError(path, "ASCII data holds at most " + std::to_string(text.size() / 2 + 1) +
                                  " numbers but the header says " + std::to_string(count));
    }
    const std::size_t width = sampleBytes(type);
    std::vector<std::byte> raw(count * width);
    const char* p = text.data();
    const char* end = text.data() + text.size();
    for (std::size_t n = 0; n < count; ++n) {
        while (p < end && (*p == ' ' || *p == '\t' || *p == '\n' || *p == '\r' || *p == ',')) {
            ++p;
        }
        double v = 0.0;
        const auto [next, ec] = std::from_chars(p, end, v);
        if (ec != std::errc{} || !storeAs(type, v, raw.data() + n * width)) {
            throw ScanError(path, "ASCII data: value " + std::to_string(n) + " of " +
                                      std::to_string(count) + " is missing or not a valid " +
                                      sampleTypeName(type));
        }
        p = next;
    }
    return decodeVolume(
        path, geometry, type,
        std::endian::native == std::endian::big ? ByteOrder::Big : ByteOrder::Little, raw);
}

} // namespace steerseg::scan
