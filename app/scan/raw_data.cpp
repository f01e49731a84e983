#include "scan/raw_data.hpp"

#include "scan/byte_source.hpp"
#include "scan/load_checks.hpp"
#include "scan/scan_reader.hpp"

#include <memory>

namespace steerseg::scan {

Volume loadRawData(const std::filesystem::path& headerPath, SeekableSource& headerFile,
                   const RawDataSpec& spec, const ReadLimits& limits) {
    std::unique_ptr<FileSource> detached;
    SeekableSource* file = &headerFile;
    std::filesystem::path where = headerPath;
    if (spec.dataFile.empty()) {
        headerFile.seek(spec.headerBytes);
    } else {
        const std::filesystem::path named(spec.dataFile);
        where = named.is_absolute() ? named : headerPath.parent_path() / named;
        try {
            detached = std::make_unique<FileSource>(where);
        } catch (const ScanError& e) {
            throw ScanError(headerPath, "data file: " + std::string(e.what()));
        }
        file = detached.get();
    }
    if (!skipLines(*file, spec.lineSkip)) {
        throw ScanError(where, "line skip " + std::to_string(spec.lineSkip) +
                                   " goes past the end of the data");
    }
    const auto& dims = spec.geometry.dims;
    const std::uint64_t dataBytes = spec.geometry.voxelCount() * sampleBytes(spec.type);
    const std::string expected = expectedDataText("header", dims, spec.type);
    if (spec.fileSkip < 0) {
        if (file->size() < dataBytes) {
            throw ScanError(where, expected + " but the file holds only " + sizeText(file->size()));
        }
        file->seek(file->size() - dataBytes);
    } else if (skipBytes(*file, static_cast<std::uint64_t>(spec.fileSkip)) <
               static_cast<std::uint64_t>(spec.fileSkip)) {
        throw ScanError(where, "byte skip " + std::to_string(spec.fileSkip) +
                                   " goes past the end of the data");
    }

    switch (spec.encoding) {
    case DataEncoding::Raw: {
        checkDataFits(where, dataBytes, *file, limits, expected);
        const auto raw = readExactly(where, *file, dataBytes, expected);
        return decodeVolume(where, spec.geometry, spec.type, spec.order, raw);
    }
    case DataEncoding::Compressed: {
        GzipSource gz(where, *file);
        if (skipBytes(gz, spec.decodedSkip) < spec.decodedSkip) {
            throw ScanError(where, "byte skip " + std::to_string(spec.decodedSkip) +
                                       " goes past the end of the decompressed data");
        }
        checkDataFits(where, dataBytes, gz, limits, expected);
        const auto raw = readExactly(where, gz, dataBytes, expected);
        return decodeVolume(where, spec.geometry, spec.type, spec.order, raw);
    }
    case DataEncoding::Ascii: {
        checkDataFits(where, dataBytes, *file, limits, expected);
        // Every number takes a character and a separator (the last one none): a 1 KiB file
        // cannot make us allocate a gigavoxel volume.
        const std::uint64_t left = *file->remaining();
        if (spec.geometry.voxelCount() > left / 2 + 1) {
            throw ScanError(where, expected + " but " + sizeText(left) +
                                       " of ascii data hold at most " +
                                       std::to_string(left / 2 + 1) + " numbers");
        }
        const auto text = readUpTo(*file, left);
        return decodeAsciiVolume(
            where, spec.geometry, spec.type,
            std::string_view(reinterpret_cast<const char*>(text.data()), text.size()));
    }
    }
    throw ScanError(where, "unknown data encoding");
}

} // namespace steerseg::scan
