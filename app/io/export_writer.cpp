#include "io/export_writer.hpp"

#include "io/dicom_seg_writer.hpp"
#include "io/mesh_writer.hpp"
#include "io/scan_reader.hpp"
#include "io/surface_mesh.hpp"
#include "io/tiff_writer.hpp"

#include <vector>

namespace steerseg::io {

namespace {

ExportSummary writeSurface(const std::filesystem::path& path, MeshFormat format,
                           const ExportData& data) {
    if (data.mask.size() != data.geometry.voxelCount() ||
        (!data.phi.empty() && data.phi.size() != data.geometry.voxelCount())) {
        throw WriteError(path, "the segmentation does not match the scan's grid " +
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

ExportSummary writeExport(const std::filesystem::path& path, ExportFormat format,
                          const ExportData& data) {
    switch (format) {
    case ExportFormat::NiftiGz:
    case ExportFormat::Nifti:
    case ExportFormat::Nrrd:
        writeMask(path, data.geometry, data.mask);
        return {};
    case ExportFormat::SegNrrd:
        writeSegmentation(path, data.geometry, data.mask, data.segment);
        return {};
    case ExportFormat::DicomSeg: {
        DicomSegOptions options;
        options.label = data.segment.name;
        writeDicomSeg(path, data.geometry, data.mask, data.dicom, options);
        return {};
    }
    case ExportFormat::Stl:
        return writeSurface(path, MeshFormat::Stl, data);
    case ExportFormat::Ply:
        return writeSurface(path, MeshFormat::Ply, data);
    case ExportFormat::Tiff: {
        writeTiffStack(path, data.geometry, data.mask);
        ExportSummary summary;
        summary.note = kTiffGeometryNote;
        return summary;
    }
    }
    throw WriteError(path, "unknown export format");
}

} // namespace steerseg::io
