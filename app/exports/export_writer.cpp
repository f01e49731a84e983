#include "exports/export_writer.hpp"

#include "core/mask_field.hpp"
#include "core/mask_measurements.hpp"
#include "core/surface_mesh.hpp"
#include "exports/dicom_seg_writer.hpp"
#include "exports/measurement_report.hpp"
#include "exports/mesh_writer.hpp"
#include "exports/tiff_writer.hpp"
#include "scan/scan_reader.hpp"

#include <vector>

namespace steerseg::exports {

namespace {

ExportSummary writeSurface(const std::filesystem::path& path, MeshFormat format,
                           const ExportData& data) {
    if (data.mask.size() != data.geometry.voxelCount() ||
        (!data.phi.empty() && data.phi.size() != data.geometry.voxelCount())) {
        throw files::WriteError(path, "the segmentation does not match the scan's grid " +
                                          std::to_string(data.geometry.voxelCount()) + " voxels");
    }
    const SurfaceMesh mesh =
        data.phi.empty() ? extractSurface(data.geometry, maskToField(data.geometry, data.mask))
                         : extractSurface(data.geometry, data.phi);
    writeMesh(path, mesh, format);
    ExportSummary summary;
    summary.triangles = mesh.triangles.size();
    summary.vertices = mesh.vertices.size();
    summary.surfaceVolumeMm3 = enclosedVolume(mesh);
    return summary;
}

// The SEG first (it refuses a scan not from DICOM, an empty mask, a mask off the grid), then
// its measurement report, which names the SEG's instance and segment.
ExportSummary writeSegAndReport(const std::filesystem::path& path, const ExportData& data) {
    DicomSegOptions options;
    options.label = data.segment.name;
    const SegInstance seg = writeDicomSeg(path, data.geometry, data.mask, data.dicom, options);
    ExportSummary summary;
    if (data.scan == nullptr) {
        return summary;
    }
    const std::filesystem::path reportPath = measurementReportPathFor(path);
    ReportedSegment segment;
    segment.number = seg.segmentNumber;
    segment.label = options.label;
    segment.finding = options.type;
    try {
        segment.measurements = measureMask(*data.scan, data.mask);
        writeMeasurementReport(reportPath, *data.dicom, seg, std::span(&segment, 1));
    } catch (const std::exception& e) {
        // The SEG is on disk already; say so, since the export as a whole failed.
        std::string problem = e.what();
        if (const std::string named = reportPath.string() + ": "; problem.starts_with(named)) {
            problem.erase(0, named.size());
        }
        throw files::WriteError(reportPath,
                                problem + " (the DICOM SEG " + path.string() + " was written)");
    }
    summary.companions.push_back(reportPath);
    return summary;
}

} // namespace

ExportSummary writeExport(const std::filesystem::path& path, model::ExportFormat format,
                          const ExportData& data) {
    switch (format) {
    case model::ExportFormat::NiftiGz:
    case model::ExportFormat::Nifti:
    case model::ExportFormat::Nrrd:
        writeMask(path, data.geometry, data.mask);
        return {};
    case model::ExportFormat::SegNrrd:
        writeSegmentation(path, data.geometry, data.mask, data.segment);
        return {};
    case model::ExportFormat::DicomSeg:
        return writeSegAndReport(path, data);
    case model::ExportFormat::Stl:
        return writeSurface(path, MeshFormat::Stl, data);
    case model::ExportFormat::Ply:
        return writeSurface(path, MeshFormat::Ply, data);
    case model::ExportFormat::Tiff: {
        writeTiffStack(path, data.geometry, data.mask);
        ExportSummary summary;
        summary.note = kTiffGeometryNote;
        return summary;
    }
    }
    throw files::WriteError(path, "unknown export format");
}

} // namespace steerseg::exports
