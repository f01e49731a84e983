#pragma once

// Masks written as a DICOM Segmentation (binary SEG, one segment per structure) that references
// the DICOM series the scan was read from, so the result goes back to the PACS with its study.
#include "core/volume.hpp"
#include "scan/dicom_source.hpp"

#include <cstdint>
#include <filesystem>
#include <glm/glm.hpp>
#include <optional>
#include <span>
#include <string>
#include <vector>

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

// One segment of a SEG.
struct DicomSegment {
    std::string label = "Segment 1";    // Segment Label (LO: at most 64 characters)
    SegmentCode category = kCodeTissue; // Segmented Property Category
    SegmentCode type = kCodeTissue;     // Segmented Property Type
    // sRGB, components 0..1: the Recommended Display CIELab Value; none written without it.
    std::optional<glm::dvec3> color{};
    std::span<const std::uint8_t> mask{}; // nonzero inside, i fastest, on the scan's grid
};

struct DicomSegSeries {
    std::string description = "steerseg segmentation";
    std::string number = "300";
};

// The one-segment call's segment and series.
struct DicomSegOptions {
    std::string label = "Segment 1";    // Segment Label (LO: at most 64 characters)
    SegmentCode category = kCodeTissue; // Segmented Property Category
    SegmentCode type = kCodeTissue;     // Segmented Property Type
    std::optional<glm::dvec3> color{};  // as DicomSegment::color
    std::string seriesDescription = "steerseg segmentation";
    std::string seriesNumber = "300";
};

// The SEG as written, for the objects that reference it (the measurement report).
struct SegInstance {
    std::string sopClassUid;
    std::string sopInstanceUid;
    std::string seriesInstanceUid;
    std::uint16_t segmentNumber = 1;             // the first segment's Segment Number
    std::vector<std::uint16_t> segmentNumbers{}; // each segment's, in the order given: 1..N
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

// Several segments in one SEG: Segment Numbers 1..N in the order given, the frames of segment 1
// (its slices holding voxels, ascending), then those of segment 2, and so on, each frame's
// Segment Identification naming its segment. Refused as the one-segment call, and for no
// segment or a segment whose mask is empty (named by its label).
SegInstance writeDicomSeg(const std::filesystem::path& path, const Geometry& geometry,
                          std::span<const DicomSegment> segments, const scan::DicomSource* source,
                          const DicomSegSeries& series = {});

} // namespace steerseg::exports
