#pragma once

// Where a text-header format (NRRD, MetaImage) keeps its voxels, and loading them.
#include "core/volume.hpp"
#include "scan/sample_decode.hpp"
#include "scan/scan_reader.hpp"

#include <filesystem>
#include <string>

namespace steerseg::scan {

class SeekableSource;

enum class DataEncoding : std::uint8_t { Raw, Compressed, Ascii }; // Compressed: gzip or zlib

struct RawDataSpec {
    Geometry geometry;
    SampleType type = SampleType::UInt8;
    ByteOrder order = ByteOrder::Little;
    DataEncoding encoding = DataEncoding::Raw;
    std::string dataFile;          // empty: attached, starting at headerBytes
    std::uint64_t headerBytes = 0; // where attached data starts in the header's file
    std::uint64_t lineSkip = 0;    // lines of the data file to skip first
    std::int64_t fileSkip = 0;     // then bytes of the file; -1: the data ends the file (raw)
    std::uint64_t decodedSkip = 0; // then bytes of the decompressed stream
};

// Reads the voxels `spec` describes: attached data from `headerFile`, detached data from
// spec.dataFile beside `headerPath`. Throws ScanError naming the file that falls short.
Volume loadRawData(const std::filesystem::path& headerPath, SeekableSource& headerFile,
                   const RawDataSpec& spec, const ReadLimits& limits);

} // namespace steerseg::scan
