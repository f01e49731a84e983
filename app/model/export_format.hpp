#pragma once

// Which file an export writes: the one place that maps a file name or a format's name to a
// format, for `steerseg export`, `steerseg segment --output` and the kiosk's export.
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace steerseg::model {

enum class ExportFormat { NiftiGz, Nifti, Nrrd, SegNrrd, DicomSeg, Stl, Ply, Tiff };

// Every format, in the order the docs list them.
const std::vector<ExportFormat>& exportFormats();

// The name --format and the config's export.formats use, which is also the extension without
// its dot: "nii.gz", "nii", "nrrd", "seg.nrrd", "dcm", "stl", "ply", "tif".
std::string_view exportFormatName(ExportFormat format);

// Every name, comma separated, for messages.
std::string exportFormatNames();

// By name, case-insensitive, a leading dot allowed, "tiff" for "tif"; nullopt when unknown.
std::optional<ExportFormat> exportFormatNamed(std::string_view name);

// By the file's extension, case-insensitive, the longest match first (".seg.nrrd" before
// ".nrrd"; ".tiff" too); nullopt for any other.
std::optional<ExportFormat> exportFormatOfFile(const std::filesystem::path& path);

// A surface mesh (STL, PLY) rather than voxels on the scan's grid.
bool isSurfaceFormat(ExportFormat format);

// The format for writing `path`: `formatOverride` when given, else the extension's. A voxel
// format named by `formatOverride` must agree with the extension, since the readers (ours and
// everyone's) choose by the name; a mesh or a TIFF may be written under any name. Throws
// std::invalid_argument with one line for the user otherwise.
ExportFormat exportFormatFor(const std::filesystem::path& path,
                             const std::optional<std::string>& formatOverride);

} // namespace steerseg::model
