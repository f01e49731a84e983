#include "exports/structure_export.hpp"

#include "core/mask_field.hpp"
#include "core/mask_measurements.hpp"
#include "core/surface_mesh.hpp"
#include "exports/label_description.hpp"
#include "exports/measurement_report.hpp"
#include "exports/mesh_writer.hpp"
#include "exports/slicer_segmentation.hpp"
#include "exports/tiff_writer.hpp"
#include "files/file_error.hpp"

#include <map>
#include <string>
#include <vector>

namespace steerseg::exports {

namespace {

std::string named(const StructureLayer& s) {
    return "structure '" + s.segment.name + "'";
}

void checkStructure(const std::filesystem::path& path, const Geometry& g, const StructureLayer& s,
                    std::size_t index) {
    const SegmentInfo& info = s.segment;
    if (info.name.empty()) {
        throw files::WriteError(path, "structure " + std::to_string(index + 1) + " has no name");
    }
    if (info.name.find_first_of("\r\n|") != std::string::npos) {
        throw files::WriteError(path, "structure " + std::to_string(index + 1) +
                                          ": a name must not hold a line break or '|'");
    }
    if (info.label < 1 || info.label > 255) {
        throw files::WriteError(path, named(s) + ": the label value must be within 1..255 (got " +
                                          std::to_string(info.label) + ")");
    }
    for (int c = 0; c < 3; ++c) {
        if (!(info.color[c] >= 0.0 && info.color[c] <= 1.0)) {
            throw files::WriteError(path, named(s) + ": colour components must be within 0..1");
        }
    }
    const std::string grid =
        " but the grid " + dimsText(g.dims) + " has " + std::to_string(g.voxelCount());
    if (s.mask.size() != g.voxelCount()) {
        throw files::WriteError(path, named(s) + ": the mask has " + std::to_string(s.mask.size()) +
                                          " voxels" + grid);
    }
    if (!s.phi.empty() && s.phi.size() != g.voxelCount()) {
        throw files::WriteError(path, named(s) + ": the level set has " +
                                          std::to_string(s.phi.size()) + " values" + grid);
    }
}

void checkStructures(const std::filesystem::path& path, const StructuresExport& data) {
    if (data.structures.empty()) {
        throw files::WriteError(path, "no structure to export");
    }
    std::map<std::string, const StructureLayer*> names;
    std::map<int, const StructureLayer*> labels;
    for (std::size_t n = 0; n < data.structures.size(); ++n) {
        const StructureLayer& s = data.structures[n];
        checkStructure(path, data.geometry, s, n);
        if (!names.emplace(s.segment.name, &s).second) {
            throw files::WriteError(path, "two structures are named '" + s.segment.name + "'");
        }
        if (const auto [at, added] = labels.emplace(s.segment.label, &s); !added) {
            throw files::WriteError(path, named(*at->second) + " and " + named(s) +
                                              " have the same label value " +
                                              std::to_string(s.segment.label));
        }
    }
}

// The SEG first (it refuses a scan not from DICOM and an empty structure), then its measurement
// report, which names the SEG's instance and segments.
ExportSummary writeSegAndReport(const std::filesystem::path& path, const StructuresExport& data) {
    std::vector<DicomSegment> segments;
    for (const StructureLayer& s : data.structures) {
        segments.push_back({s.segment.name, s.category, s.type, s.segment.color, s.mask});
    }
    const SegInstance seg = writeDicomSeg(path, data.geometry, segments, data.dicom);
    ExportSummary summary;
    if (data.scan == nullptr) {
        return summary;
    }
    const std::filesystem::path reportPath = measurementReportPathFor(path);
    try {
        std::vector<ReportedSegment> reported;
        for (std::size_t n = 0; n < data.structures.size(); ++n) {
            const StructureLayer& s = data.structures[n];
            ReportedSegment r;
            r.number = seg.segmentNumbers[n];
            r.label = s.segment.name;
            r.finding = s.type;
            r.measurements = measureMask(*data.scan, s.mask);
            reported.push_back(std::move(r));
        }
        writeMeasurementReport(reportPath, *data.dicom, seg, reported);
    } catch (const std::exception& e) {
        // The SEG is on disk already; say so, since the export as a whole failed.
        std::string problem = e.what();
        if (const std::string prefix = reportPath.string() + ": "; problem.starts_with(prefix)) {
            problem.erase(0, prefix.size());
        }
        throw files::WriteError(reportPath,
                                problem + " (the DICOM SEG " + path.string() + " was written)");
    }
    summary.companions.push_back(reportPath);
    return summary;
}

// One structure: the 0/1 mask. Several: their label values, a later structure's over an earlier
// one's, with the names beside.
ExportSummary writeVoxels(const std::filesystem::path& path, const StructuresExport& data) {
    if (data.structures.size() == 1) {
        writeMask(path, data.geometry, data.structures.front().mask);
        return {};
    }
    std::vector<std::uint8_t> labels(data.geometry.voxelCount(), 0);
    std::size_t shared = 0;
    for (std::size_t n = 0; n < labels.size(); ++n) {
        int inside = 0;
        for (const StructureLayer& s : data.structures) {
            if (s.mask[n] != 0) {
                labels[n] = static_cast<std::uint8_t>(s.segment.label);
                ++inside;
            }
        }
        shared += inside > 1 ? 1 : 0;
    }
    writeLabelMap(path, data.geometry, labels);
    std::vector<SegmentInfo> names;
    for (const StructureLayer& s : data.structures) {
        names.push_back(s.segment);
    }
    const std::filesystem::path description = labelDescriptionPathFor(path);
    writeLabelDescription(description, names);
    ExportSummary summary;
    summary.companions.push_back(description);
    if (shared > 0) {
        summary.note = std::to_string(shared) +
                       " voxels lie in more than one structure; the label map gives each the "
                       "label of the later structure in the list (.seg.nrrd keeps them all)";
    }
    return summary;
}

ExportSummary writeSlicer(const std::filesystem::path& path, const StructuresExport& data) {
    std::vector<SlicerSegment> segments;
    for (const StructureLayer& s : data.structures) {
        segments.push_back({s.segment, s.mask});
    }
    writeSegmentation(path, data.geometry, segments);
    return {};
}

SurfaceMesh surfaceOf(const Geometry& g, const StructureLayer& s) {
    return s.phi.empty() ? extractSurface(g, maskToField(g, s.mask)) : extractSurface(g, s.phi);
}

// Every mesh is made before any file is written, so that an empty structure leaves none.
ExportSummary writeSurfaces(const std::filesystem::path& path, MeshFormat format,
                            const StructuresExport& data) {
    std::vector<SurfaceMesh> meshes;
    for (const StructureLayer& s : data.structures) {
        meshes.push_back(surfaceOf(data.geometry, s));
        // One structure: writeMesh's own words, as before there were several.
        if (data.structures.size() > 1 && meshes.back().empty()) {
            throw files::WriteError(path, named(s) +
                                              " has no surface (nothing is inside it), so no "
                                              "mesh was written");
        }
    }
    ExportSummary summary;
    for (std::size_t n = 0; n < meshes.size(); ++n) {
        const std::filesystem::path file =
            structureMeshPathFor(path, n, data.structures[n].segment);
        writeMesh(file, meshes[n], format);
        summary.triangles += meshes[n].triangles.size();
        summary.vertices += meshes[n].vertices.size();
        summary.surfaceVolumeMm3 += enclosedVolume(meshes[n]);
        if (n > 0) {
            summary.companions.push_back(file);
        }
    }
    return summary;
}

ExportSummary writeTiff(const std::filesystem::path& path, const StructuresExport& data) {
    if (data.structures.size() > 1) {
        throw files::WriteError(path, "TIFF holds one structure; choose NIfTI, NRRD, .seg.nrrd or "
                                      "DICOM SEG for several, or export one structure");
    }
    writeTiffStack(path, data.geometry, data.structures.front().mask);
    ExportSummary summary;
    summary.note = kTiffGeometryNote;
    return summary;
}

} // namespace

std::filesystem::path structureMeshPathFor(const std::filesystem::path& path, std::size_t index,
                                           const SegmentInfo& segment) {
    if (index == 0) {
        return path;
    }
    std::string name = segment.name;
    for (char& c : name) {
        const bool kept = (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') ||
                          (c >= '0' && c <= '9') || c == '-' || c == '_';
        c = kept ? c : '_';
    }
    return path.parent_path() / (path.stem().string() + "_" + std::to_string(segment.label) + "_" +
                                 name + path.extension().string());
}

ExportSummary writeStructures(const std::filesystem::path& path, model::ExportFormat format,
                              const StructuresExport& data) {
    checkStructures(path, data);
    switch (format) {
    case model::ExportFormat::NiftiGz:
    case model::ExportFormat::Nifti:
    case model::ExportFormat::Nrrd:
        return writeVoxels(path, data);
    case model::ExportFormat::SegNrrd:
        return writeSlicer(path, data);
    case model::ExportFormat::DicomSeg:
        return writeSegAndReport(path, data);
    case model::ExportFormat::Stl:
        return writeSurfaces(path, MeshFormat::Stl, data);
    case model::ExportFormat::Ply:
        return writeSurfaces(path, MeshFormat::Ply, data);
    case model::ExportFormat::Tiff:
        return writeTiff(path, data);
    }
    throw files::WriteError(path, "unknown export format");
}

} // namespace steerseg::exports
