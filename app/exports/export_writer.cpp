#include "exports/export_writer.hpp"

#include "exports/dicom_seg_writer.hpp"
#include "exports/mesh_writer.hpp"
#include "exports/surface_mesh.hpp"
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
    const SurfaceMesh mesh = data.phi.empty()
                                 ? extractSurface(data.geometry, maskToField(data.mask))
                                 : extractSurface(data.geometry, data.phi);
    writeMesh(path, mesh, format);
    ExportSummary summary;
    summary.triangles = mesh.triangles.size();
    summary.vertices = mesh.vertices.size();
    summary.surfaceVolumeMm3 = enclosedVolume(mesh);
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
    case model::ExportFormat::DicomSeg: {
        DicomSegOptions options;
        options.label = data.segment.name;
        writeDicomSeg(path, data.geometry, data.mask, data.dicom, options);
        return {};
    }
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
