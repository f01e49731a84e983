#pragma once

// One segmentation out in any export format: the switch over model::ExportFormat.
#include "core/volume.hpp"
#include "exports/mask_writer.hpp"
#include "model/export_format.hpp"
#include "scan/dicom_source.hpp"

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <span>
#include <string>
#include <vector>

namespace steerseg::exports {

// What is exported: the mask on the scan's grid and, where there is one, the level set itself.
struct ExportData {
    Geometry geometry;
    std::span<const std::uint8_t> mask; // non-zero inside, i fastest
    // The level set (phi < 0 inside, i fastest). Surfaces come from its zero crossing; empty:
    // from the mask (crossings halfway between inside and outside voxel centres).
    std::span<const float> phi;
    SegmentInfo segment; // for .seg.nrrd and DICOM SEG (its name is the segment label)
    // The DICOM series the scan was read from (LoadedScan::dicom): DICOM SEG refers to it and
    // refuses without it.
    const scan::DicomSource* dicom = nullptr;
    // The scan itself (its real values: HU on CT), on `geometry`. With it a DICOM SEG is written
    // with its measurement report beside it (exports/measurement_report); the product's exports
    // always give it, a test of the SEG alone may not.
    const Volume* scan = nullptr;
};

// What a caller reports after the write.
struct ExportSummary {
    std::size_t triangles = 0; // surfaces only
    std::size_t vertices = 0;
    double surfaceVolumeMm3 = 0.0;
    std::string note; // a caveat to show the user (TIFF's missing geometry), or empty
    // Files written beside the one asked for: a DICOM SEG's measurement report (X.sr.dcm).
    std::vector<std::filesystem::path> companions;
};

// Writes `data` to `path` as `format` says, durably (files::writeFileAtomically). Throws
// files::WriteError with one line.
ExportSummary writeExport(const std::filesystem::path& path, model::ExportFormat format,
                          const ExportData& data);

} // namespace steerseg::exports
