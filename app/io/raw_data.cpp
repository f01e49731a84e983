#include "io/raw_data.hpp"

#include "io/byte_source.hpp"
#include "io/scan_reader.hpp"

#include <memory>

namespace steerseg::io {

Volume loadRawData(const std::filesystem::path& headerPath, SeekableSource& headerFile,
                   const RawDataSpec& spec) {
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
    if (spec.fileSkip < 0) {
        if (file->size() < dataBytes) {
            throw ScanError(where, expectedDataText("header", dims, spec.type) +
                                       " but the file holds only " + sizeText(file->size()));
        }
        file->seek(file->size() - dataBytes);
    } else if (skipBytes(*file, static_cast<std::uint64_t>(spec.fileSkip)) <
               static_cast<std::uint64_t>(spec.fileSkip)) {
        throw ScanError(where, "byte skip " + std::to_string(spec.fileSkip) +
                                   " goes past the end of the data");
    }

    switch (spec.encoding) {
    case DataEncoding::Raw: {
        const auto raw =
            readExactly(where, *file, dataBytes, expectedDataText("header", dims, spec.type));
        return decodeVolume(where, spec.geometry, spec.type, spec.order, raw);
    }
    case DataEncoding::Compressed: {
        GzipSource gz(where, *file);
        if (skipBytes(gz, spec.decodedSkip) < spec.decodedSkip) {
            throw ScanError(where, "byte skip " + std::to_string(spec.decodedSkip) +
                                       " goes past the end of the decompressed data");
        }
        const auto raw =
            readExactly(where, gz, dataBytes, expectedDataText("header", dims, spec.type));
        return decodeVolume(where, spec.geometry, spec.type, spec.order, raw);
    }
    case DataEncoding::Ascii: {
        const auto text = readUpTo(*file, *file->remaining());
        return decodeAsciiVolume(
            where, spec.geometry, spec.type,
            std::string_view(reinterpret_cast<const char*>(text.data()), text.size()));
    }
    }
    throw ScanError(where, "unknown data encoding");
}

} // namespace steerseg::io
