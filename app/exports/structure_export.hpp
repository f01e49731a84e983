#pragma once

// Every structure of a session (liver, spleen, kidney: each a name, a coded meaning, a colour and
// a mask on the scan's grid) out in one export format; docs/exports.md, "Several structures".
// writeExport writes one structure through this same code.
#include "core/volume.hpp"
#include "exports/dicom_seg_writer.hpp"
#include "exports/export_writer.hpp"
#include "exports/mask_writer.hpp"
#include "model/export_format.hpp"
#include "scan/dicom_source.hpp"

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <span>
#include <vector>

namespace steerseg::exports {

struct StructureLayer {
    // Name (a DICOM segment's label, a Slicer segment's name, the label map's description),
    // colour (r g b within 0..1) and label value (1..255, the label map's and Slicer's voxel
    // value); the id and tags are Slicer's.
    SegmentInfo segment{};
    SegmentCode category = kCodeTissue;   // DICOM Segmented Property Category (CID 7150)
    SegmentCode type = kCodeTissue;       // Segmented Property Type (CID 7151): the SR's finding
    std::span<const std::uint8_t> mask{}; // non-zero inside, i fastest, on the geometry's grid
    // The level set (phi < 0 inside, i fastest): surfaces from its zero crossing; empty: from
    // the mask.
    std::span<const float> phi{};
};

struct StructuresExport {
    Geometry geometry{};
    std::vector<StructureLayer> structures{}; // in the session's order
    // The DICOM series the scan was read from: DICOM SEG refers to it and refuses without it.
    const scan::DicomSource* dicom = nullptr;
    // The scan's real values on `geometry`: with it a DICOM SEG gets its measurement report.
    const Volume* scan = nullptr;
};

// Writes every structure of `data` to `path` as `format`, durably. One structure: exactly
// writeExport's file. Several:
// - DICOM SEG: one SEG, segment k+1 for structure k, and beside it (with `scan`) its
//   measurement report, one group per segment (companions: the report);
// - .seg.nrrd: one segment per structure, in one layer where none overlap, else one layer each;
// - NIfTI, NRRD: a label map (each structure's label value; where structures overlap, the later
//   one's, said in `note`) and its ITK-SNAP label description X.label.txt (companions);
// - STL, PLY: one mesh per structure, the first at `path`, structure k beside it as
//   structureMeshPathFor says (companions, in order); the summary's counts are the sums;
// - TIFF: refused (it holds one structure).
// Throws files::WriteError with one line: no structure; a structure without a name, with a '|'
// or line break in it, or named as another; a label outside 1..255 or another's; a colour
// outside 0..1; a mask or level set off the grid; an empty structure in a SEG or a mesh; any
// format's own refusal.
ExportSummary writeStructures(const std::filesystem::path& path, model::ExportFormat format,
                              const StructuresExport& data);

// Where structure `index` (0-based) of a mesh export goes: `path` for the first, else
// `<stem>_<label>_<name>.<ext>` beside it, the name's characters other than letters, digits, '-'
// and '_' as '_'.
std::filesystem::path structureMeshPathFor(const std::filesystem::path& path, std::size_t index,
                                           const SegmentInfo& segment);

} // namespace steerseg::exports
