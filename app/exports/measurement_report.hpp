#pragma once

// The measurements of a DICOM SEG's segments as a DICOM SR Measurement Report (TID 1500), written
// beside the SEG so that a PACS viewer shows the figures `steerseg measure` prints with the
// segmentation they belong to. One measurement group (TID 1411) per segment; docs/exports.md
// lists the codes and why they were chosen.
#include "core/mask_measurements.hpp"
#include "exports/dicom_seg_writer.hpp"
#include "scan/dicom_source.hpp"

#include <cstdint>
#include <filesystem>
#include <optional>
#include <span>
#include <string>

namespace steerseg::exports {

// One segment of the SEG and what was measured of it (core/mask_measurements, on the scan's
// real values).
struct ReportedSegment {
    std::uint16_t number = 1;          // its Segment Number in the SEG
    std::string label;                 // the SEG's Segment Label: the group's Tracking Identifier
    SegmentCode finding = kCodeTissue; // the SEG's Segmented Property Type
    std::optional<SegmentCode> site;   // Finding Site, where known
    MaskMeasurements measurements;
};

struct MeasurementReportOptions {
    // The person observer. The configuration names no operator, so the role stands in.
    std::string observerName = "Operator";
    std::string deviceUid; // the device observer's UID; empty: applianceDeviceUid()
    std::string seriesDescription = "steerseg measurements";
    std::string seriesNumber = "301"; // the SEG's series is 300
};

// `X.dcm` -> `X.sr.dcm` (any other name, `.DCM` included, gets `.sr.dcm` appended): where the
// report of the SEG written to `segPath` goes. Inline: the light build names it too.
inline std::filesystem::path measurementReportPathFor(const std::filesystem::path& segPath) {
    std::string name = segPath.string();
    if (name.ends_with(".dcm")) {
        name.resize(name.size() - 4);
    }
    return name + ".sr.dcm";
}

// A UID for this appliance that stays the same across runs: 2.25 followed by the machine id
// (/etc/machine-id, 128 bits) in decimal, as PS3.5 B.2 derives UIDs from UUIDs; a fresh UID
// where the machine has no id.
std::string applianceDeviceUid();

// Writes the report of `segments` of the SEG `seg`, drawn on the series `source`, to `path`
// as an Enhanced SR in the source's study, atomically (files::writeFileAtomically). Throws
// files::WriteError with one line: no segment, a segment with no voxel inside, a source without
// study or series UID, DCMTK refusing the content, or a failed write.
void writeMeasurementReport(const std::filesystem::path& path, const scan::DicomSource& source,
                            const SegInstance& seg, std::span<const ReportedSegment> segments,
                            const MeasurementReportOptions& options = {});

} // namespace steerseg::exports
