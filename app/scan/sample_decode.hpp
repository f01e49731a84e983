#pragma once

// Turning a file's raw samples into a Volume: byte order, and the mapping from the many on-disk
// sample types to the four the app stores.
#include "core/volume.hpp"

#include <cstdint>
#include <filesystem>
#include <optional>
#include <span>
#include <string_view>

namespace steerseg::scan {

enum class SampleType : std::uint8_t {
    Int8,
    UInt8,
    Int16,
    UInt16,
    Int32,
    UInt32,
    Int64,
    UInt64,
    Float32,
    Float64
};

std::size_t sampleBytes(SampleType type);
const char* sampleTypeName(SampleType type); // "int8" ... "float64"

// uint8, int16, uint16 and float32 stay as they are; int8 widens to int16; every other type
// becomes float32 (32/64-bit integers past 2^24 lose precision, which no scan intensity needs).
VoxelType storedTypeFor(SampleType type);

enum class ByteOrder : std::uint8_t { Little, Big };

// Builds a Volume on `geometry` from `raw` (exactly voxelCount * sampleBytes bytes, i fastest),
// converting byte order and type. Float results are checked finite (ScanError naming `path`).
Volume decodeVolume(const std::filesystem::path& path, const Geometry& geometry, SampleType type,
                    ByteOrder order, std::span<const std::byte> raw);

// The same from ASCII numbers separated by white space or commas (NRRD "ascii" encoding).
// Throws ScanError for a missing, malformed or out-of-range number.
Volume decodeAsciiVolume(const std::filesystem::path& path, const Geometry& geometry,
                         SampleType type, std::string_view text);

// "header says 512x512x300 int16 (150 MiB)": the start of a short-data message.
std::string expectedDataText(const char* who, const glm::ivec3& dims, SampleType type);

} // namespace steerseg::scan
