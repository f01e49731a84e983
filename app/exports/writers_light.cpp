// The light build's stand-ins for the two export formats whose libraries the GPU pack leaves
// out (TIFF: OpenImageIO; DICOM SEG and its measurement report: DCMTK): refused by name, as a
// write that cannot be made.
// NIfTI, NRRD, the Slicer segmentation and the meshes are the full build's own.
#include "exports/dicom_seg_writer.hpp"
#include "exports/measurement_report.hpp"
#include "exports/tiff_writer.hpp"
#include "files/file_error.hpp"
#include "model/light_build.hpp"

namespace steerseg::exports {

void writeTiffStack(const std::filesystem::path& path, const Geometry& /*geometry*/,
                    std::span<const std::uint8_t> /*mask*/) {
    throw files::WriteError(path, model::leftOutOfLightBuild("The TIFF export", "OpenImageIO"));
}

SegInstance writeDicomSeg(const std::filesystem::path& path, const Geometry& /*geometry*/,
                          std::span<const std::uint8_t> /*mask*/,
                          const scan::DicomSource* /*source*/, const DicomSegOptions& /*options*/) {
    throw files::WriteError(path, model::leftOutOfLightBuild("The DICOM SEG export", "DCMTK"));
}

SegInstance writeDicomSeg(const std::filesystem::path& path, const Geometry& /*geometry*/,
                          std::span<const DicomSegment> /*segments*/,
                          const scan::DicomSource* /*source*/, const DicomSegSeries& /*series*/) {
    throw files::WriteError(path, model::leftOutOfLightBuild("The DICOM SEG export", "DCMTK"));
}

void writeMeasurementReport(const std::filesystem::path& path, const scan::DicomSource& /*source*/,
                            const SegInstance& /*seg*/,
                            std::span<const ReportedSegment> /*segments*/,
                            const MeasurementReportOptions& /*options*/) {
    throw files::WriteError(path,
                            model::leftOutOfLightBuild("The DICOM measurement report", "DCMTK"));
}

} // namespace steerseg::exports
