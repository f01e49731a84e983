#include "model/export_format.hpp"

#include "model/file_name.hpp"

#include <stdexcept>

namespace steerseg::model {

const std::vector<ExportFormat>& exportFormats() {
    static const std::vector<ExportFormat> all{
        ExportFormat::NiftiGz,  ExportFormat::Nifti, ExportFormat::Nrrd, ExportFormat::SegNrrd,
        ExportFormat::DicomSeg, ExportFormat::Stl,   ExportFormat::Ply,  ExportFormat::Tiff};
    return all;
}

std::string_view exportFormatName(ExportFormat format) {
    switch (format) {
    case ExportFormat::NiftiGz:
        return "nii.gz";
    case ExportFormat::Nifti:
        return "nii";
    case ExportFormat::Nrrd:
        return "nrrd";
    case ExportFormat::SegNrrd:
        return "seg.nrrd";
    case ExportFormat::DicomSeg:
        return "dcm";
    case ExportFormat::Stl:
        return "stl";
    case ExportFormat::Ply:
        return "ply";
    case ExportFormat::Tiff:
        return "tif";
    }
    return "";
}

std::string exportFormatNames() {
    std::string out;
    for (const ExportFormat f : exportFormats()) {
        out += (out.empty() ? "" : ", ") + std::string(exportFormatName(f));
    }
    return out;
}

std::optional<ExportFormat> exportFormatNamed(std::string_view name) {
    std::string lower = lowerCase(std::string(name));
    if (!lower.empty() && lower.front() == '.') {
        lower.erase(0, 1);
    }
    if (lower == "tiff") {
        return ExportFormat::Tiff;
    }
    for (const ExportFormat f : exportFormats()) {
        if (lower == exportFormatName(f)) {
            return f;
        }
    }
    return std::nullopt;
}

std::optional<ExportFormat> exportFormatOfFile(const std::filesystem::path& path) {
    const std::string name = lowerFileName(path);
    if (hasSuffix(name, ".tiff")) {
        return ExportFormat::Tiff;
    }
    std::optional<ExportFormat> best;
    std::size_t longest = 0;
    for (const ExportFormat f : exportFormats()) {
        const std::string suffix = "." + std::string(exportFormatName(f));
        if (hasSuffix(name, suffix) && name.size() > suffix.size() && suffix.size() > longest) {
            best = f;
            longest = suffix.size();
        }
    }
    return best;
}

bool isSurfaceFormat(ExportFormat format) {
    return format == ExportFormat::Stl || format == ExportFormat::Ply;
}

ExportFormat exportFormatFor(const std::filesystem::path& path,
                             const std::optional<std::string>& formatOverride) {
    const std::optional<ExportFormat> byName = exportFormatOfFile(path);
    if (!formatOverride) {
        if (!byName) {
            throw std::invalid_argument("--output " + path.string() +
                                        ": cannot tell the format from the extension (" +
                                        exportFormatNames() + "); name it or give --format");
        }
        return *byName;
    }
    const std::optional<ExportFormat> chosen = exportFormatNamed(*formatOverride);
    if (!chosen) {
        throw std::invalid_argument("--format: unknown format '" + *formatOverride + "' (" +
                                    exportFormatNames() + ")");
    }
    const bool anyName = isSurfaceFormat(*chosen) || *chosen == ExportFormat::Tiff;
    // ".seg.nrrd" is an ".nrrd" too: a plain NRRD may be written under that name.
    const bool agrees =
        byName == chosen || (*chosen == ExportFormat::Nrrd && byName == ExportFormat::SegNrrd);
    if (!anyName && !agrees) {
        throw std::invalid_argument("--format " + std::string(exportFormatName(*chosen)) +
                                    " needs an output ending in ." +
                                    std::string(exportFormatName(*chosen)));
    }
    return *chosen;
}

} // namespace steerseg::model
