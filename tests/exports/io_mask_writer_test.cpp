#include "exports/mask_writer.hpp"
#include "scan/scan_reader.hpp"
#include "support/io_test_files.hpp"
#include "support/test_data.hpp"

#include <cstring>
#include <fstream>
#include <gtest/gtest.h>
#include <nifti2_io.h>

namespace steerseg::test {
namespace {

std::vector<std::uint8_t> sphereMask(const glm::ivec3& dims) {
    std::vector<std::uint8_t> m;
    const glm::dvec3 c = glm::dvec3(dims - 1) / 2.0;
    for (int k = 0; k < dims.z; ++k) {
        for (int j = 0; j < dims.y; ++j) {
            for (int i = 0; i < dims.x; ++i) {
                // Off-centre and asymmetric, so an axis flip would show.
                const double d = glm::length((glm::dvec3(i, j, k) - c) / glm::dvec3(dims));
                m.push_back(d < 0.3 && i > 2 ? 1 : 0);
            }
        }
    }
    return m;
}

// Written then read back: the same grid (oblique, left-handed) and the same voxels.
TEST(MaskWriter, RoundTripsEveryFormat) {
    for (const char* ext : {".nii.gz", ".nii", ".nrrd"}) {
        SCOPED_TRACE(ext);
        const glm::ivec3 dims(11, 9, 7);
        const Geometry g = test::obliqueGeometry(dims);
        const auto mask = sphereMask(dims);
        const auto dir = test::tempDir("mask-roundtrip");
        const auto file = dir / (std::string("mask") + ext);
        exports::writeMask(file, g, mask);
        const scan::LoadedScan scan = scan::readScan(file);
        EXPECT_EQ(scan.volume.type(), VoxelType::UInt8);
        test::expectSameGeometry(scan.volume.geometry(), g, 1e-5);
        const auto v = scan.volume.voxels<std::uint8_t>();
        ASSERT_EQ(v.size(), mask.size());
        EXPECT_TRUE(std::equal(v.begin(), v.end(), mask.begin()));
        EXPECT_EQ(scan.volume.rescale().slope, 1.0);
        // Nothing but the mask is left in the folder (the temporary file was renamed).
        EXPECT_EQ(std::distance(std::filesystem::directory_iterator(dir), {}), 1);
    }
}

// The header fields ITK-SNAP and Slicer go by: both transforms set as scanner anatomy, no
// scaling, millimetres, and the sform equal to the grid in RAS.
TEST(MaskWriter, NiftiHeaderFields) {
    const Geometry g = test::obliqueGeometry({4, 5, 6});
    const auto dir = test::tempDir("mask-header");
    exports::writeMask(dir / "m.nii", g, std::vector<std::uint8_t>(g.voxelCount(), 1));
    std::ifstream in(dir / "m.nii", std::ios::binary);
    nifti_1_header h{};
    in.read(reinterpret_cast<char*>(&h), sizeof h);
    EXPECT_EQ(h.sizeof_hdr, 348);
    EXPECT_EQ(std::memcmp(h.magic, "n+1", 4), 0);
    EXPECT_EQ(h.sform_code, NIFTI_XFORM_SCANNER_ANAT);
    EXPECT_EQ(h.qform_code, NIFTI_XFORM_SCANNER_ANAT);
    EXPECT_EQ(h.scl_slope, 0.0f);
    EXPECT_EQ(h.datatype, NIFTI_TYPE_UINT8);
    EXPECT_EQ(h.vox_offset, 352.0f);
    EXPECT_EQ(h.xyzt_units & 7, NIFTI_UNITS_MM);
    // RAS = LPS with x and y negated; srow holds direction * spacing and the origin.
    for (int c = 0; c < 3; ++c) {
        const glm::dvec3 col = g.direction[c] * g.spacing[c];
        EXPECT_NEAR(h.srow_x[c], -col.x, 1e-5);
        EXPECT_NEAR(h.srow_y[c], -col.y, 1e-5);
        EXPECT_NEAR(h.srow_z[c], col.z, 1e-5);
    }
    EXPECT_NEAR(h.srow_x[3], -g.origin.x, 1e-4);
    EXPECT_NEAR(h.srow_y[3], -g.origin.y, 1e-4);
    EXPECT_NEAR(h.srow_z[3], g.origin.z, 1e-4);
}

TEST(MaskWriter, NrrdHeaderIsLps) {
    const Geometry g = test::obliqueGeometry({4, 5, 6});
    const auto dir = test::tempDir("mask-nrrd");
    exports::writeMask(dir / "m.nrrd", g, std::vector<std::uint8_t>(g.voxelCount(), 0));
    std::ifstream in(dir / "m.nrrd", std::ios::binary);
    std::string text(4096, '\0');
    in.read(text.data(), static_cast<std::streamsize>(text.size()));
    text.resize(static_cast<std::size_t>(in.gcount()));
    EXPECT_NE(text.find("space: left-posterior-superior\n"), std::string::npos);
    EXPECT_NE(text.find("encoding: gzip\n"), std::string::npos);
    EXPECT_NE(text.find("space directions: ("), std::string::npos);
    EXPECT_NE(text.find("space origin: (-12.5,40.25,7)\n"), std::string::npos);
}

TEST(MaskWriter, NonZeroBecomesOne) {
    Geometry g;
    g.dims = {3, 1, 1};
    const auto dir = test::tempDir("mask-binary");
    exports::writeMask(dir / "m.nii.gz", g, std::vector<std::uint8_t>{0, 7, 255});
    const Volume v = scan::readScan(dir / "m.nii.gz").volume;
    EXPECT_EQ(v.valueAt(0, 0, 0), 0.0);
    EXPECT_EQ(v.valueAt(1, 0, 0), 1.0);
    EXPECT_EQ(v.valueAt(2, 0, 0), 1.0);
}

TEST(MaskWriter, RefusesBadInput) {
    Geometry g;
    g.dims = {2, 2, 2};
    const auto dir = test::tempDir("mask-bad");
    EXPECT_THROW(exports::writeMask(dir / "m.nii.gz", g, std::vector<std::uint8_t>(7)),
                 files::WriteError);
    EXPECT_THROW(exports::writeMask(dir / "m.png", g, std::vector<std::uint8_t>(8)),
                 files::WriteError);
    EXPECT_THROW(exports::writeMask(dir / "missing" / "m.nii", g, std::vector<std::uint8_t>(8)),
                 files::WriteError);
    g.spacing.y = 0.0;
    EXPECT_THROW(exports::writeMask(dir / "m.nrrd", g, std::vector<std::uint8_t>(8)),
                 scan::ScanError);
    EXPECT_TRUE(std::filesystem::is_empty(dir));
}

// A mask written on a real scan's grid lands where the scan is: same world centroid.
TEST(MaskWriter, OverlaysRealScan) {
    STEERSEG_REQUIRE_DATA(file, "head-mr-seg3d/seg3d_brain_mask_on_MR.nii.gz");
    const Volume m = scan::readScan(file).volume;
    const auto v = m.voxels<std::uint8_t>();
    const auto dir = test::tempDir("mask-real");
    for (const char* ext : {".nii.gz", ".nrrd"}) {
        exports::writeMask(dir / (std::string("brain") + ext), m.geometry(), {v.data(), v.size()});
        const Volume back = scan::readScan(dir / (std::string("brain") + ext)).volume;
        const glm::dvec3 d = test::worldCentroid(back) - test::worldCentroid(m);
        EXPECT_LT(glm::length(d), 1e-3) << ext;
    }
}

} // namespace
} // namespace steerseg::test
