#pragma once

// A mask written as a DICOM Segmentation (binary SEG, one segment) that references the DICOM
// series the scan was read from, so the result goes back to the PACS with its study.
#include "core/volume.hpp"
#include "scan/dicom_source.hpp"

#include <cstdint>
#include <filesystem>
#include <span>
#include <string>

namespace steerseg::exports {

// A coded concept: (code value, coding scheme designator, code meaning).
struct SegmentCode {
    std::string value;
    std::string scheme;
    std::string meaning;
};

// SNOMED CT concepts of CID 7150 (category) and CID 7151 (type).
inline const SegmentCode kCodeTissue{"85756007", "SCT", "Tissue"};
inline const SegmentCode kCodeMorphologicallyAbnormalStructure{
    "49755003", "SCT", "Morphologically Abnormal Structure"};
inline const SegmentCode kCodeMass{"4147007", "SCT", "Mass"};

struct DicomSegOptions {
    std::string label = "Segment 1";    // Segment Label (LO: at most 64 characters)
    SegmentCode category = kCodeTissue; // Segmented Property Category
    SegmentCode type = kCodeTissue;     // Segmented Property Type
    std::string seriesDescription = "steerseg segmentation";
    std::string seriesNumber = "300";
};

// The SEG as written, for the objects that reference it (the measurement report).
struct SegInstance {
    std::string sopClassUid;
    std::string sopInstanceUid;
    std::string seriesInstanceUid;
    std::uint16_t segmentNumber = 1; // the one segment's Segment Number
};

// Writes `mask` (one uint8 per voxel on `geometry`'s grid, i fastest, nonzero inside) as a binary
// DICOM SEG to `path`, atomically (files::writeFileAtomically). `geometry` and `source` are those
// of the scan the mask was drawn on (scan::LoadedScan::dicom); only slices holding segmented voxels
// become frames (docs/dicom.md). Throws WriteError with one line: no DICOM source ("DICOM SEG
// needs a scan read from a DICOM series"), a mask or source that does not match the grid, an
// empty mask, a source without a Frame of Reference or instance UIDs, or a failed write.
SegInstance writeDicomSeg(const std::filesystem::path& path, const Geometry& geometry,
                          std::span<const std::uint8_t> mask, const scan::DicomSource* source,
                          const DicomSegOptions& options = {});

} // namespace steerseg::exports
