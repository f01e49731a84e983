// steerseg export: a mask already made (by `segment` or another tool) written again on the scan's
// grid, as a mask or as a surface mesh. GL-free: it needs no GPU, only the two files.
#include "cli/args.hpp"
#include "cli/commands.hpp"
#include "io/file_name.hpp"
#include "io/mask_writer.hpp"
#include "io/mesh_writer.hpp"
#include "io/scan_reader.hpp"
#include "io/surface_mesh.hpp"

#include <algorithm>
#include <cstdio>
#include <nlohmann/json.hpp>

namespace steerseg::cli {

namespace {

constexpr const char* kFormats[] = {"stl", "ply", "nii.gz", "nii", "nrrd"};

// The format's name, from --format or the output's extension.
std::string chooseFormat(const Args& args, const std::string& output) {
    const std::string name = io::lowerFileName(output);
    std::string byName;
    for (const char* f : kFormats) {
        if (io::hasSuffix(name, std::string(".") + f)) {
            byName = f;
            break;
        }
    }
    const auto requested = args.value("format");
    if (!requested) {
        if (byName.empty()) {
            throw UsageError("--output " + output +
                             ": cannot tell the format from the extension (.stl, .ply, .nii.gz, "
                             ".nii, .nrrd); name it or give --format");
        }
        return byName;
    }
    std::string format = io::lowerCase(*requested);
    if (!format.empty() && format.front() == '.') {
        format.erase(0, 1);
    }
    if (std::none_of(std::begin(kFormats), std::end(kFormats),
                     [&](const char* f) { return format == f; })) {
        throw UsageError("--format: unknown format '" + *requested +
                         "' (stl, ply, nii.gz, nii, nrrd)");
    }
    // A mask's writer knows its format by the name only; a mesh's can be told.
    if (format != "stl" && format != "ply" && format != byName) {
        throw UsageError("--format " + format + " needs an output ending in ." + format);
    }
    return format;
}

// The mask as 0/1 on the scan's grid. It must be on that grid: the same dimensions and, within
// what a file header's float precision leaves, the same placement in the patient.
std::vector<std::uint8_t> readMaskFor(const std::string& path, const Geometry& scan) {
    const io::LoadedScan mask = io::readScan(path);
    const Geometry& g = mask.volume.geometry();
    if (g.dims != scan.dims) {
        throw io::ScanError(path, "the mask is " + std::to_string(g.dims.x) + "x" +
                                      std::to_string(g.dims.y) + "x" + std::to_string(g.dims.z) +
                                      " voxels but the scan is " + std::to_string(scan.dims.x) +
                                      "x" + std::to_string(scan.dims.y) + "x" +
                                      std::to_string(scan.dims.z));
    }
    const double far = glm::length(scan.indexToWorld(glm::dvec3(scan.dims - 1)) -
                                   g.indexToWorld(glm::dvec3(g.dims - 1)));
    const double near = glm::length(scan.origin - g.origin);
    const double tolerance = 0.01 * std::min({scan.spacing.x, scan.spacing.y, scan.spacing.z});
    if (std::max(near, far) > tolerance) {
        throw io::ScanError(path, "the mask is not on the scan's grid (its corner voxels lie " +
                                      std::to_string(std::max(near, far)) + " mm from the scan's)");
    }
    std::vector<std::uint8_t> inside(g.voxelCount());
    for (std::size_t n = 0; n < inside.size(); ++n) {
        inside[n] = mask.volume.rescale().apply(mask.volume.storedAt(n)) > 0.5 ? 1 : 0;
    }
    return inside;
}

} // namespace

int runExport(std::span<const std::string> words) {
    const Args args(words, {"input", "mask", "output", "format"}, {});
    if (!args.positional().empty()) {
        throw UsageError("unexpected argument '" + args.positional().front() + "'");
    }
    const std::string input = args.required("input");
    const std::string maskPath = args.required("mask");
    const std::string output = args.required("output");
    const std::string format = chooseFormat(args, output);

    const io::LoadedScan scan = io::readScan(input);
    const Geometry& geometry = scan.volume.geometry();
    const std::vector<std::uint8_t> mask = readMaskFor(maskPath, geometry);
    const auto insideVoxels = std::count(mask.begin(), mask.end(), std::uint8_t{1});
    const double voxelVolume = geometry.spacing.x * geometry.spacing.y * geometry.spacing.z;

    nlohmann::ordered_json report;
    report["input"] = input;
    report["mask"] = maskPath;
    report["output"] = output;
    report["format"] = format;
    report["mask_volume_mm3"] = static_cast<double>(insideVoxels) * voxelVolume;
    if (format == "stl" || format == "ply") {
        const io::SurfaceMesh mesh = io::extractSurface(geometry, io::maskToField(mask));
        io::writeMesh(output, mesh, format == "stl" ? io::MeshFormat::Stl : io::MeshFormat::Ply);
        report["triangles"] = mesh.triangles.size();
        report["vertices"] = mesh.vertices.size();
        report["surface_volume_mm3"] = io::enclosedVolume(mesh);
    } else {
        io::writeMask(output, geometry, mask);
    }
    report["world"] = "LPS";
    std::printf("%s\n", report.dump(2).c_str());
    return 0;
}

} // namespace steerseg::cli
