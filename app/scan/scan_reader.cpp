#include "scan/scan_reader.hpp"

#include "core/sample_phantom.hpp"
#include "model/file_name.hpp"
#include "scan/readers.hpp"
#include "scan/series_state.hpp"

#include <algorithm>
#include <cctype>
#include <fstream>

namespace steerseg::scan {

namespace {

bool folderHoldsDicom(const std::filesystem::path& dir) {
    std::error_code ec;
    for (const auto& entry : std::filesystem::directory_iterator(dir, ec)) {
        if (entry.is_regular_file(ec) && looksLikeDicom(entry.path())) {
            return true;
        }
    }
    return false;
}

LoadedScan readDicomScan(const std::filesystem::path& path, const ReadLimits& limits) {
    auto source = std::make_shared<DicomSource>();
    Volume volume = readDicom(path, limits, source.get());
    return {std::move(volume), "dicom", std::move(source)};
}

} // namespace

bool looksLikeDicom(const std::filesystem::path& path) {
    std::ifstream in(path, std::ios::binary);
    char magic[132] = {};
    if (!in.read(magic, sizeof magic)) {
        return false;
    }
    return std::string_view(magic + 128, 4) == "DICM";
}

LoadedScan readScan(const std::filesystem::path& path, const ReadLimits& limits) {
    if (path == kBuiltinSample) {
        return {makeSamplePhantom(), "builtin"};
    }
    std::error_code ec;
    const auto status = std::filesystem::status(path, ec);
    if (ec || !std::filesystem::exists(status)) {
        throw ScanError(path, "no such file or folder");
    }
    if (std::filesystem::is_directory(status)) {
        if (std::filesystem::is_empty(path, ec)) {
            throw ScanError(path, "the folder is empty");
        }
        // A series the DICOM node is receiving, or one an association left unfinished, is not
        // read as if whole (issue 48), whoever asks: the load screen, a script, the command line.
        const SeriesState state = seriesState(path);
        if (state.receiving) {
            throw ScanError(path, "the series is still arriving (an association is writing it): "
                                  "load it once it is whole");
        }
        if (state.incomplete) {
            throw ScanError(path, "an incomplete series: the association that sent it ended "
                                  "before it finished; a whole send of the series makes it "
                                  "whole again");
        }
        if (folderHoldsDicom(path)) {
            return readDicomScan(path, limits);
        }
        return {readImageStack(path, limits), "image-stack"};
    }
    if (!std::filesystem::is_regular_file(status)) {
        throw ScanError(path, "not a regular file");
    }
    const std::string name = model::lowerFileName(path);
    if (model::hasSuffix(name, ".nii") || model::hasSuffix(name, ".nii.gz")) {
        std::string format;
        Volume v = readNifti(path, limits, format);
        return {std::move(v), format};
    }
    if (model::hasSuffix(name, ".nrrd") || model::hasSuffix(name, ".nhdr")) {
        return {readNrrd(path, limits), "nrrd"};
    }
    if (model::hasSuffix(name, ".mha") || model::hasSuffix(name, ".mhd")) {
        return {readMetaImage(path, limits), "metaimage"};
    }
    if (model::hasSuffix(name, ".mgz") || model::hasSuffix(name, ".mgh")) {
        return {readMgz(path, limits), "mgz"};
    }
    if (model::hasSuffix(name, ".dcm") || looksLikeDicom(path)) {
        return readDicomScan(path, limits);
    }
    // A multi-page TIFF is a stack; any other single 2D image is a one-slice volume.
    for (const char* ext : {".tif", ".tiff", ".png", ".jpg", ".jpeg", ".bmp", ".pgm", ".ppm",
                            ".pnm", ".exr", ".webp", ".tga"}) {
        if (model::hasSuffix(name, ext)) {
            return {readImageStack(path, limits), "image-stack"};
        }
    }
    throw ScanError(path, "unrecognised scan format (expected DICOM, .nii[.gz], .nrrd/.nhdr, "
                          ".mha/.mhd, .mgz/.mgh, .tif[f], a 2D image or a folder of images)");
}

} // namespace steerseg::scan
