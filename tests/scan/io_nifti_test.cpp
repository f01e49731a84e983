#include "scan/byte_source.hpp"
#include "scan/readers.hpp"
#include "scan/scan_reader.hpp"
#include "support/io_test_files.hpp"
#include "support/test_data.hpp"

#include <algorithm>
#include <cmath>
#include <gtest/gtest.h>
#include <nifti2_io.h>

namespace steerseg::test {
namespace {

using test::pattern;

struct RealNifti {
    const char* file;
    glm::ivec3 dims;
    glm::dvec3 spacing;
    VoxelType type;
    double slope;
};

// One test process per file would cost more in start-up (OpenImageIO, GDCM) than the reads.
const RealNifti kRealNiftis[] = {
    RealNifti{
        "brain-mni152/spm152.nii.gz", {207, 256, 215}, glm::dvec3(0.7375), VoxelType::UInt8, 0.363},
    RealNifti{"brain-mni152/mni152_pveseg.nii.gz",
              {207, 256, 215},
              glm::dvec3(0.7375),
              VoxelType::UInt8,
              1.0},
    RealNifti{
        "head-mr-seg3d/MR.nii.gz", {160, 232, 160}, {1.0, 0.898, 0.898}, VoxelType::UInt8, 2.0078},
    RealNifti{"brain-stroke/T1.nii.gz", {124, 160, 140}, glm::dvec3(1.0), VoxelType::UInt8, 1.0},
    RealNifti{"brain-stroke/T2.nii.gz", {124, 160, 140}, glm::dvec3(1.0), VoxelType::UInt8, 2.0078},
    RealNifti{"brain-stroke/FLAIR.nii.gz", {124, 160, 140}, glm::dvec3(1.0), VoxelType::UInt8, 1.0},
    RealNifti{"thigh-sarcoma-sts001/STS_001_CT_image.nii.gz",
              {198, 202, 59},
              {0.977, 0.977, 3.27},
              VoxelType::Float32,
              1.0},
    RealNifti{"thigh-sarcoma-sts001/STS_001_MR_T1_image.nii.gz",
              {174, 158, 59},
              {0.977, 0.977, 3.27},
              VoxelType::Float32,
              1.0},
    RealNifti{"thigh-sarcoma-sts001/STS_001_CT_mask.nii.gz",
              {198, 202, 59},
              {0.977, 0.977, 3.27},
              VoxelType::UInt8,
              1.0},
    RealNifti{"abdomen-ct-totalseg/example_ct_sm.nii.gz",
              {122, 101, 30},
              glm::dvec3(3.0),
              VoxelType::Int16,
              1.0},
    RealNifti{"abdomen-ct-totalseg/example_mr_sm.nii.gz",
              {117, 91, 20},
              glm::dvec3(3.0),
              VoxelType::Int16,
              1.0},
    RealNifti{"abdomen-ct-totalseg/totalseg_example_ct_dicom_HU.nii.gz",
              {512, 512, 20},
              {0.977, 0.977, 2.0},
              VoxelType::Int16,
              1.0},
    RealNifti{"lung-ct-ibsi/nifti/image.nii.gz",
              {204, 201, 60},
              {0.977, 0.977, 3.0},
              VoxelType::Float32,
              1.0},
    RealNifti{"lung-ct-ibsi/nifti/mask.nii.gz",
              {204, 201, 60},
              {0.977, 0.977, 3.0},
              VoxelType::UInt8,
              1.0}};

// Dims, spacing, type and scl_slope as SOURCES.md lists them.
TEST(NiftiReader, SharedDataMatchesSources) {
    STEERSEG_REQUIRE_DATA(dir, "brain-mni152");
    for (const RealNifti& want : kRealNiftis) {
        SCOPED_TRACE(want.file);
        const auto file = test::dataPath(want.file);
        ASSERT_TRUE(file) << "missing " << want.file;
        const scan::LoadedScan scan = scan::readScan(*file);
        EXPECT_EQ(scan.format, "nifti");
        EXPECT_EQ(scan.volume.dims(), want.dims);
        for (int a = 0; a < 3; ++a) {
            EXPECT_NEAR(scan.volume.geometry().spacing[a], want.spacing[a], 1e-3);
        }
        EXPECT_EQ(scan.volume.type(), want.type);
        EXPECT_NEAR(scan.volume.rescale().slope, want.slope, 1e-3);
    }
}

// SOURCES.md's tissue means (CSF 22, GM 140, WM 194) are in stored units; real values are
// those times scl_slope 0.363 (about 8, 51, 70).
TEST(NiftiReader, SclSlopeScalesTissueMeans) {
    STEERSEG_REQUIRE_DATA(image, "brain-mni152/spm152.nii.gz");
    STEERSEG_REQUIRE_DATA(labels, "brain-mni152/mni152_pveseg.nii.gz");
    const Volume v = scan::readScan(image).volume;
    const Volume l = scan::readScan(labels).volume;
    ASSERT_EQ(v.dims(), l.dims());
    const std::vector<float> real = v.realValues();
    const auto lab = l.voxels<std::uint8_t>();
    double stored[4] = {};
    double sum[4] = {};
    double count[4] = {};
    for (std::size_t n = 0; n < real.size(); ++n) {
        if (lab[n] >= 1 && lab[n] <= 3) {
            stored[lab[n]] += v.storedAt(n);
            sum[lab[n]] += static_cast<double>(real[n]);
            count[lab[n]] += 1.0;
        }
    }
    const double want[4] = {0.0, 22.0, 140.0, 194.0};
    for (int t = 1; t <= 3; ++t) {
        EXPECT_NEAR(stored[t] / count[t], want[t], 2.0) << "tissue " << t;
        EXPECT_NEAR(sum[t] / count[t], want[t] * 0.363, 1.0) << "tissue " << t;
    }
}

// The thigh files carry only a qform (sform_code 0).
TEST(NiftiReader, QformOnlyFileIsPlaced) {
    STEERSEG_REQUIRE_DATA(file, "thigh-sarcoma-sts001/STS_001_CT_image.nii.gz");
    STEERSEG_REQUIRE_DATA(mask, "thigh-sarcoma-sts001/STS_001_CT_mask.nii.gz");
    const Volume v = scan::readScan(file).volume;
    const Volume m = scan::readScan(mask).volume;
    test::expectSameGeometry(v.geometry(), m.geometry());
    EXPECT_GT(v.stats().max, 1000.0); // HU
}

struct TypeCase {
    int datatype;
    const char* sample;
    VoxelType stored;
};

const TypeCase kTypes[] = {{NIFTI_TYPE_UINT8, "uint8", VoxelType::UInt8},
                           {NIFTI_TYPE_INT8, "int8", VoxelType::Int16},
                           {NIFTI_TYPE_INT16, "int16", VoxelType::Int16},
                           {NIFTI_TYPE_UINT16, "uint16", VoxelType::UInt16},
                           {NIFTI_TYPE_INT32, "int32", VoxelType::Float32},
                           {NIFTI_TYPE_UINT32, "uint32", VoxelType::Float32},
                           {NIFTI_TYPE_FLOAT32, "float32", VoxelType::Float32},
                           {NIFTI_TYPE_FLOAT64, "float64", VoxelType::Float32}};

// Every accepted datatype, NIfTI-1 and -2, either byte order, on an oblique left-handed grid.
TEST(NiftiReader, AllTypesVersionsAndByteOrders) {
    const glm::ivec3 dims(5, 4, 3);
    const Geometry g = test::obliqueGeometry(dims);
    const auto dir = test::tempDir("nifti-types");
    for (const TypeCase& tc : kTypes) {
        for (const int version : {1, 2}) {
            for (const bool bigEndian : {false, true}) {
                SCOPED_TRACE(std::string(tc.sample) + " NIfTI-" + std::to_string(version) +
                             (bigEndian ? " big-endian" : " little-endian"));
                test::NiftiOptions o;
                o.version = version;
                o.datatype = tc.datatype;
                o.bigEndian = bigEndian;
                test::writeFile(dir / "t.nii",
                                test::niftiFile(g,
                                                test::encodeSamples(test::patternValues(dims),
                                                                    tc.sample, bigEndian),
                                                o));
                const scan::LoadedScan scan = scan::readScan(dir / "t.nii");
                EXPECT_EQ(scan.format, version == 2 ? "nifti2" : "nifti");
                EXPECT_EQ(scan.volume.type(), tc.stored);
                test::expectSameGeometry(scan.volume.geometry(), g);
                for (int k = 0; k < dims.z; ++k) {
                    for (int j = 0; j < dims.y; ++j) {
                        for (int i = 0; i < dims.x; ++i) {
                            ASSERT_EQ(scan.volume.valueAt(i, j, k), pattern(i, j, k))
                                << i << "," << j << "," << k;
                        }
                    }
                }
            }
        }
    }
}

Geometry readGeometry(const Geometry& g, const test::NiftiOptions& o) {
    const auto dir = test::tempDir("nifti-xform");
    test::writeFile(dir / "x.nii", test::niftiFile(g, std::vector<std::byte>(g.voxelCount()), o));
    return scan::readScan(dir / "x.nii").volume.geometry();
}

TEST(NiftiReader, QformUsedWithoutSform) {
    const Geometry g = test::obliqueGeometry({3, 3, 3});
    test::NiftiOptions o;
    o.sformCode = 0;
    test::expectSameGeometry(readGeometry(g, o), g);
}

// Neither transform: pixdim alone on RAS axes, which in LPS point along -x and -y.
TEST(NiftiReader, PixdimOnlyWithoutTransforms) {
    const Geometry g = test::obliqueGeometry({3, 3, 3});
    test::NiftiOptions o;
    o.sformCode = 0;
    o.qformCode = 0;
    const Geometry r = readGeometry(g, o);
    EXPECT_EQ(r.spacing, g.spacing);
    EXPECT_EQ(r.origin, glm::dvec3(0.0));
    EXPECT_EQ(r.direction,
              glm::dmat3(glm::dvec3(-1, 0, 0), glm::dvec3(0, -1, 0), glm::dvec3(0, 0, 1)));
}

TEST(NiftiReader, SclSlopeAndInterBecomeRescale) {
    const Geometry g = test::obliqueGeometry({2, 2, 2});
    test::NiftiOptions o;
    o.datatype = NIFTI_TYPE_INT16;
    o.slope = 0.5;
    o.inter = -1024.0;
    const auto dir = test::tempDir("nifti-scl");
    test::writeFile(
        dir / "s.nii",
        test::niftiFile(g, test::encodeSamples(std::vector<double>(8, 100.0), "int16"), o));
    const Volume v = scan::readScan(dir / "s.nii").volume;
    EXPECT_DOUBLE_EQ(v.valueAt(1, 1, 1), 50.0 - 1024.0);
}

TEST(NiftiReader, SingleVolume4DIsAccepted) {
    const Geometry g = test::obliqueGeometry({2, 2, 2});
    test::NiftiOptions o;
    o.volumes = 1;
    EXPECT_EQ(readGeometry(g, o).dims, glm::ivec3(2, 2, 2));
}

TEST(NiftiReader, GzipAndPlainGiveTheSameVolume) {
    STEERSEG_REQUIRE_DATA(file, "brain-stroke/T2.nii.gz");
    scan::FileSource compressed(file);
    scan::GzipSource gz(file, compressed);
    const auto dir = test::tempDir("nifti-plain");
    test::writeFile(dir / "T2.nii", scan::readUpTo(gz, std::uint64_t{1} << 30));
    const Volume a = scan::readScan(file).volume;
    const Volume b = scan::readScan(dir / "T2.nii").volume;
    ASSERT_EQ(a.bytes().size(), b.bytes().size());
    EXPECT_TRUE(std::equal(a.bytes().begin(), a.bytes().end(), b.bytes().begin()));
    EXPECT_EQ(a.geometry().origin, b.geometry().origin);
    EXPECT_EQ(a.rescale().slope, b.rescale().slope);
}

} // namespace
} // namespace steerseg::test
