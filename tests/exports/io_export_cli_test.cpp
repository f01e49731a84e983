// `steerseg export` end to end: a mask on an oblique scan's grid out as STL, PLY and NRRD, and
// the mistakes a user makes each answered with one line and the documented exit status.
#include "exports/mask_writer.hpp"
#include "scan/scan_reader.hpp"
#include "support/cli_run.hpp"
#include "support/test_data.hpp"

#include <cmath>
#include <cstring>
#include <fstream>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

namespace steerseg::test {
namespace {

struct Files {
    std::filesystem::path dir;
    std::filesystem::path scan;
    std::filesystem::path mask;
    Geometry geometry;
    glm::dvec3 centre{0.0};       // world
    glm::dvec3 maskCentroid{0.0}; // world, of the inside voxels' centres
    double radius = 9.0;          // mm
};

// A sphere mask on a rotated grid away from the origin; the scan is a mask-like uint8 file on
// the same grid (its voxels do not matter to export).
Files makeFiles(const std::string& name) {
    Files f;
    f.dir = tempDir(name);
    f.scan = f.dir / "scan.nii.gz";
    f.mask = f.dir / "mask.nii.gz";
    Geometry& g = f.geometry;
    g.dims = {36, 30, 24};
    g.spacing = {0.8, 1.1, 1.5};
    g.origin = {-60.0, 25.0, 140.0};
    const double a = 0.4;
    g.direction = glm::dmat3(glm::dvec3(std::cos(a), std::sin(a), 0.0),
                             glm::dvec3(-std::sin(a), std::cos(a), 0.0), glm::dvec3(0.0, 0.0, 1.0));
    f.centre = g.indexToWorld({17.3, 14.6, 11.2});
    std::vector<std::uint8_t> mask(g.voxelCount());
    double inside = 0.0;
    for (int k = 0; k < g.dims.z; ++k) {
        for (int j = 0; j < g.dims.y; ++j) {
            for (int i = 0; i < g.dims.x; ++i) {
                const glm::dvec3 w = g.indexToWorld(glm::dvec3(i, j, k));
                if (glm::distance(w, f.centre) < f.radius) {
                    mask[linearIndex(g.dims, i, j, k)] = 1;
                    f.maskCentroid += w;
                    inside += 1.0;
                }
            }
        }
    }
    f.maskCentroid /= inside;
    exports::writeMask(f.scan, g, std::vector<std::uint8_t>(g.voxelCount(), 1));
    exports::writeMask(f.mask, g, mask);
    return f;
}

CliRun runExport(const Files& f, const std::string& output, const std::string& extra = "") {
    return runSteerseg("export --input " + f.scan.string() + " --mask " + f.mask.string() +
                       " --output " + (f.dir / output).string() + extra);
}

void expectOneLine(const CliRun& r, const std::string& needle) {
    ASSERT_FALSE(r.err.empty());
    EXPECT_EQ(r.err.find('\n'), r.err.size() - 1) << "more than one line: " << r.err;
    EXPECT_NE(r.err.find(needle), std::string::npos) << r.err;
}

TEST(CliExport, SurfaceMeshesSitOnTheMaskInPatientCoordinates) {
    const Files f = makeFiles("export-mesh");
    for (const std::string out : {"s.stl", "s.ply", "s.mesh"}) {
        SCOPED_TRACE(out);
        const CliRun r = runExport(f, out, out == "s.mesh" ? " --format STL" : "");
        ASSERT_EQ(r.exitCode, 0) << r.err;
        const auto j = nlohmann::json::parse(r.out);
        EXPECT_EQ(j.at("world"), "LPS");
        const double surface = j.at("surface_volume_mm3");
        const double voxels = j.at("mask_volume_mm3");
        // The mask's smooth surface (core/mask_field maskToField) rounds off inside the
        // boundary voxels: a few % under the voxel count for this 9 mm sphere, less for larger.
        EXPECT_LT(std::abs(surface - voxels) / voxels, 0.06) << surface << " vs " << voxels;
        EXPECT_GT(j.at("triangles").get<std::size_t>(), 100u);
    }
    // The solid the STL encloses has the mask's centroid in patient coordinates, and its
    // vertices lie on the mask's boundary.
    std::ifstream in(f.dir / "s.stl", std::ios::binary);
    std::string bytes(std::filesystem::file_size(f.dir / "s.stl"), '\0');
    in.read(bytes.data(), static_cast<std::streamsize>(bytes.size()));
    std::uint32_t count = 0;
    std::memcpy(&count, bytes.data() + 80, 4);
    ASSERT_EQ(bytes.size(), 84 + 50 * std::size_t{count});
    glm::dvec3 moment(0.0);
    double volume = 0.0;
    double worst = 0.0;
    for (std::size_t n = 0; n < count; ++n) {
        std::array<float, 9> v{};
        std::memcpy(v.data(), bytes.data() + 84 + 50 * n + 12, 36);
        std::array<glm::dvec3, 3> p{};
        for (std::size_t c = 0; c < 3; ++c) {
            p[c] = glm::dvec3(v[3 * c], v[3 * c + 1], v[3 * c + 2]) - f.centre;
            worst = std::max(worst, std::abs(glm::length(p[c]) - f.radius));
        }
        // The tetrahedron from the centre to the facet.
        const double tet = glm::dot(p[0], glm::cross(p[1], p[2])) / 6.0;
        volume += tet;
        moment += tet * (p[0] + p[1] + p[2]) / 4.0;
    }
    const glm::dvec3 centroid = f.centre + moment / volume;
    EXPECT_LT(glm::distance(centroid, f.maskCentroid), 0.1)
        << "mesh centroid " << centroid.x << "," << centroid.y << "," << centroid.z;
    EXPECT_LT(worst, 1.5) << "a vertex far from the mask's boundary";
}

TEST(CliExport, MaskFormatsRoundTripOnTheScansGrid) {
    const Files f = makeFiles("export-mask");
    const CliRun r = runExport(f, "m.nrrd");
    ASSERT_EQ(r.exitCode, 0) << r.err;
    const scan::LoadedScan back = scan::readScan(f.dir / "m.nrrd");
    const scan::LoadedScan original = scan::readScan(f.mask);
    ASSERT_EQ(back.volume.dims(), f.geometry.dims);
    EXPECT_LT(glm::distance(back.volume.geometry().origin, f.geometry.origin), 1e-3);
    for (std::size_t n = 0; n < f.geometry.voxelCount(); ++n) {
        ASSERT_EQ(back.volume.storedAt(n), original.volume.storedAt(n)) << n;
    }
}

// Every other format by its extension and by --format: the Slicer segmentation and a TIFF stack
// read back with the mask's voxels; the TIFF's missing geometry is said in the output.
TEST(CliExport, EveryFormatByExtensionAndByFormat) {
    const Files f = makeFiles("export-every");
    const scan::LoadedScan original = scan::readScan(f.mask);
    for (const auto& [out, extra] : std::vector<std::pair<std::string, std::string>>{
             {"m.seg.nrrd", ""}, {"m.nii", ""}, {"m.nii.gz", " --format .NII.GZ"}}) {
        SCOPED_TRACE(out);
        const CliRun r = runExport(f, out, extra);
        ASSERT_EQ(r.exitCode, 0) << r.err;
        EXPECT_EQ(nlohmann::json::parse(r.out).at("world"), "LPS");
        const scan::LoadedScan back = scan::readScan(f.dir / out);
        ASSERT_EQ(back.volume.dims(), f.geometry.dims);
        EXPECT_LT(glm::distance(back.volume.geometry().origin, f.geometry.origin), 1e-3);
        for (std::size_t n = 0; n < f.geometry.voxelCount(); ++n) {
            ASSERT_EQ(back.volume.storedAt(n) > 0, original.volume.storedAt(n) > 0) << n;
        }
    }
    for (const auto& [out, extra] : std::vector<std::pair<std::string, std::string>>{
             {"m.tif", ""}, {"m.tiff", ""}, {"m.stack", " --format tiff"}}) {
        SCOPED_TRACE(out);
        const CliRun r = runExport(f, out, extra);
        ASSERT_EQ(r.exitCode, 0) << r.err;
        const auto j = nlohmann::json::parse(r.out);
        EXPECT_EQ(j.at("format"), "tif");
        EXPECT_NE(j.at("note").get<std::string>().find("no patient position"), std::string::npos);
        EXPECT_EQ(j.at("world"), "none (voxel order)");
        std::ifstream in(f.dir / out, std::ios::binary);
        char magic[4] = {};
        in.read(magic, 4);
        EXPECT_EQ(std::string(magic, 4), std::string("II*\0", 4));
    }
    {
        const CliRun r =
            runExport(f, "named.seg.nrrd",
                      " --segment-name Tumour --segment-color 1,0.5,0 --segment-label 7");
        ASSERT_EQ(r.exitCode, 0) << r.err;
        std::ifstream in(f.dir / "named.seg.nrrd", std::ios::binary);
        std::string header(4096, '\0');
        in.read(header.data(), static_cast<std::streamsize>(header.size()));
        for (const char* line : {"\nSegment0_Name:=Tumour\n", "\nSegment0_LabelValue:=7\n",
                                 "\nSegment0_Color:=1.000000 0.500000 0.000000\n"}) {
            EXPECT_NE(header.find(line), std::string::npos) << line;
        }
        const CliRun bad = runExport(f, "bad.seg.nrrd", " --segment-label 300");
        EXPECT_EQ(bad.exitCode, 2);
        EXPECT_NE(bad.err.find("--segment-label: expected a whole number"), std::string::npos)
            << bad.err;
    }
    const CliRun dcm = runExport(f, "m.dcm");
    EXPECT_EQ(dcm.exitCode, 4);
    expectOneLine(dcm, "DICOM SEG needs a scan read from a DICOM series");
    EXPECT_FALSE(std::filesystem::exists(f.dir / "m.dcm"));
}

TEST(CliExport, MistakesGiveOneLineAndTheirExitStatus) {
    const Files f = makeFiles("export-bad");
    {
        const CliRun r = runExport(f, "s.obj");
        EXPECT_EQ(r.exitCode, 2);
        EXPECT_NE(r.err.find("cannot tell the format"), std::string::npos) << r.err;
    }
    {
        const CliRun r = runExport(f, "s.out", " --format nrrd");
        EXPECT_EQ(r.exitCode, 2);
        EXPECT_NE(r.err.find("needs an output ending in .nrrd"), std::string::npos) << r.err;
    }
    {
        // A mask from another grid (the same size, moved).
        Geometry moved = f.geometry;
        moved.origin += glm::dvec3(5.0, 0.0, 0.0);
        exports::writeMask(f.dir / "moved.nii.gz", moved,
                           std::vector<std::uint8_t>(moved.voxelCount(), 1));
        const CliRun r = runSteerseg("export --input " + f.scan.string() + " --mask " +
                                     (f.dir / "moved.nii.gz").string() + " --output " +
                                     (f.dir / "x.stl").string());
        EXPECT_EQ(r.exitCode, 1);
        expectOneLine(r, "not on the scan's grid");
    }
    {
        const auto empty = f.dir / "empty.nii.gz";
        exports::writeMask(empty, f.geometry,
                           std::vector<std::uint8_t>(f.geometry.voxelCount(), 0));
        const CliRun r = runSteerseg("export --input " + f.scan.string() + " --mask " +
                                     empty.string() + " --output " + (f.dir / "e.ply").string());
        EXPECT_EQ(r.exitCode, 4);
        expectOneLine(r, "the surface is empty");
        EXPECT_FALSE(std::filesystem::exists(f.dir / "e.ply"));
    }
    {
        const CliRun r = runExport(f, "s.nrrd", " --format jpeg");
        EXPECT_EQ(r.exitCode, 2);
        EXPECT_NE(r.err.find("--format: unknown format 'jpeg'"), std::string::npos) << r.err;
    }
    {
        const CliRun r = runExport(f, "no-such-folder/s.stl");
        EXPECT_EQ(r.exitCode, 4);
        expectOneLine(r, "the folder " + (f.dir / "no-such-folder").string() + " does not exist");
    }
}

} // namespace
} // namespace steerseg::test
