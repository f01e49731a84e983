// Hostile and broken files: each must fail with a ScanError naming the file and the problem,
// without crashing and without allocating what the file does not hold.
#include "files/file_write.hpp"
#include "scan/scan_reader.hpp"
#include "support/io_test_files.hpp"
#include "support/test_data.hpp"

#include <OpenImageIO/imageio.h>
#include <gtest/gtest.h>
#include <limits>
#include <nifti2_io.h>
#include <sys/resource.h>

namespace steerseg::test {
namespace {

// Reads `path`, expecting a ScanError whose message names the file and contains `problem`.
void expectScanError(const std::filesystem::path& path, const std::string& problem,
                     const scan::ReadLimits& limits = {}) {
    try {
        (void)scan::readScan(path, limits);
        ADD_FAILURE() << path << " was read but should have failed with \"" << problem << "\"";
    } catch (const scan::ScanError& e) {
        const std::string what = e.what();
        EXPECT_NE(what.find(path.filename().string()), std::string::npos) << what;
        EXPECT_NE(what.find(problem), std::string::npos) << what;
        EXPECT_EQ(what.find('\n'), std::string::npos) << "not one line: " << what;
    }
}

// Peak resident memory of this test process (each test runs in its own process under CTest).
double peakRssMiB() {
    rusage u{};
    getrusage(RUSAGE_SELF, &u);
    return static_cast<double>(u.ru_maxrss) / 1024.0;
}

std::vector<std::byte> smallNifti(test::NiftiOptions o = {}) {
    const Geometry g = test::obliqueGeometry({8, 8, 8});
    return test::niftiFile(g, test::encodeSamples(test::patternValues(g.dims), "uint8"), o);
}

class Hostile : public ::testing::Test {
  protected:
    std::filesystem::path dir = test::tempDir("hostile");
};

TEST_F(Hostile, TruncatedNii) {
    auto bytes = smallNifti();
    bytes.resize(bytes.size() - 100);
    test::writeFile(dir / "cut.nii", bytes);
    expectScanError(dir / "cut.nii",
                    "header says 8x8x8 uint8 (512 bytes) but the file holds only 412 bytes");
    bytes.resize(200);
    test::writeFile(dir / "short.nii", bytes);
    expectScanError(dir / "short.nii", "too short for a NIfTI header");
}

TEST_F(Hostile, TruncatedNiiGz) {
    const auto gz = files::gzipBytes(smallNifti());
    test::writeFile(dir / "cut.nii.gz",
                    std::vector<std::byte>(
                        gz.begin(), gz.begin() + static_cast<std::ptrdiff_t>(gz.size() / 2)));
    expectScanError(dir / "cut.nii.gz", "data ends after");
}

TEST_F(Hostile, GarbageGzip) {
    std::vector<std::byte> bytes = {std::byte{0x1f}, std::byte{0x8b}, std::byte{8}, std::byte{0}};
    for (int n = 0; n < 500; ++n) {
        bytes.push_back(static_cast<std::byte>((n * 37 + 11) & 0xff));
    }
    test::writeFile(dir / "junk.nii.gz", bytes);
    expectScanError(dir / "junk.nii.gz", "compressed data is corrupt");
}

// 100000^3 voxels: refused from the header, before any allocation.
TEST_F(Hostile, HugeDimensionsInHeader) {
    test::NiftiOptions o;
    o.version = 2;
    Geometry g;
    g.dims = glm::ivec3(100000);
    test::writeFile(dir / "huge.nii", test::niftiFile(g, {}, o));
    expectScanError(dir / "huge.nii", "dimensions 100000x100000x100000 exceed the limit");
    g.dims = glm::ivec3(30000); // fits NIfTI-1's int16 dims, but 2.7e13 voxels
    test::writeFile(dir / "huge1.nii", test::niftiFile(g, {}, {}));
    expectScanError(dir / "huge1.nii", "voxels) exceed the limit");
    test::writeFile(
        dir / "huge.nrrd",
        std::string(
            "NRRD0004\ntype: float\ndimension: 3\nsizes: 100000 100000 100000\nencoding: raw\n\n"));
    expectScanError(dir / "huge.nrrd", "exceed the limit");
    test::writeFile(dir / "huge.mha",
                    std::string("NDims = 3\nDimSize = 100000 100000 100000\nElementType = "
                                "MET_FLOAT\nElementDataFile = LOCAL\n"));
    expectScanError(dir / "huge.mha", "exceed the limit");
}

// 4 KiB of incompressible bytes, whose gzip could in principle expand past 4 MiB.
std::vector<std::byte> noise(std::size_t count) {
    std::vector<std::byte> out(count);
    std::uint32_t x = 12345;
    for (std::byte& b : out) {
        x = x * 1664525U + 1013904223U;
        b = static_cast<std::byte>(x >> 24);
    }
    return out;
}

// A claim the compressed bytes could meet (3.8 MiB from 4 KiB of gzip) but do not: the reader
// fails after decompressing what is there, never reserving the claimed size.
TEST_F(Hostile, ClaimedSizeNotBackedByCompressedData) {
    Geometry g;
    g.dims = glm::ivec3(100);
    test::NiftiOptions o;
    o.datatype = NIFTI_TYPE_FLOAT32;
    test::writeFile(dir / "claim.nii.gz", files::gzipBytes(test::niftiFile(g, noise(4096), o)));
    expectScanError(dir / "claim.nii.gz",
                    "header says 100x100x100 float32 (3.8 MiB) but the data ends after 4.0 KiB");
    test::writeFile(
        dir / "claim.nrrd",
        test::concat("NRRD0004\ntype: float\ndimension: 3\nsizes: 100 100 100\nencoding: gzip\n\n",
                     files::gzipBytes(noise(4096))));
    expectScanError(dir / "claim.nrrd", "but the data ends after 4.0 KiB");
    EXPECT_LT(peakRssMiB(), 512.0);
}

// Decompression bombs: a header declaring more than its compressed bytes can expand to at
// deflate's ceiling (1032:1) is refused before anything is decoded or allocated, with the numbers.
TEST_F(Hostile, DeclaredSizeBeyondWhatCompressedDataCanHold) {
    Geometry g;
    g.dims = glm::ivec3(1000); // 954 MiB of uint8: under every size limit
    const std::vector<std::byte> zeros(4096);
    test::writeFile(dir / "bomb.nii.gz", files::gzipBytes(test::niftiFile(g, zeros)));
    expectScanError(dir / "bomb.nii.gz", "header says 1000x1000x1000 uint8 (954 MiB) but ");
    expectScanError(dir / "bomb.nii.gz", " of compressed data expand to at most ");
    expectScanError(dir / "bomb.nii.gz", "(compression ratio limit 1032:1)");
    test::writeFile(
        dir / "bomb.nrrd",
        test::concat(
            "NRRD0004\ntype: uchar\ndimension: 3\nsizes: 1000 1000 1000\nencoding: gzip\n\n",
            files::gzipBytes(zeros)));
    expectScanError(dir / "bomb.nrrd", "of compressed data expand to at most");
    test::writeFile(dir / "bomb.mha",
                    test::concat("NDims = 3\nDimSize = 1000 1000 1000\nElementType = MET_UCHAR\n"
                                 "CompressedData = True\nElementDataFile = LOCAL\n",
                                 files::gzipBytes(zeros)));
    expectScanError(dir / "bomb.mha", "of compressed data expand to at most");
    test::writeFile(dir / "bomb.mgz",
                    files::gzipBytes(test::mghFile(g, 0, std::vector<double>(8))));
    expectScanError(dir / "bomb.mgz", "of compressed data expand to at most");
    // A configured ratio is stated as such: 64^3 zeros compress far better than 10:1.
    scan::ReadLimits strict;
    strict.maxCompressionRatio = 10.0;
    Geometry small;
    small.dims = glm::ivec3(64);
    test::writeFile(dir / "ratio.nii.gz",
                    files::gzipBytes(test::niftiFile(small, std::vector<std::byte>(64 * 64 * 64))));
    expectScanError(dir / "ratio.nii.gz", "(compression ratio limit 10:1)", strict);
    EXPECT_LT(peakRssMiB(), 256.0);
}

// The bound must never refuse a genuine file: an all-zero mask compresses close to deflate's
// ceiling and still reads.
TEST_F(Hostile, GenuineHighlyCompressedDataIsRead) {
    Geometry g;
    g.dims = glm::ivec3(128);
    const std::vector<std::byte> zeros(g.voxelCount());
    const auto gz = files::gzipBytes(test::niftiFile(g, zeros), 9);
    ASSERT_GT(static_cast<double>(zeros.size()) / static_cast<double>(gz.size()), 900.0);
    test::writeFile(dir / "zeros.nii.gz", gz);
    EXPECT_EQ(scan::readScan(dir / "zeros.nii.gz").volume.dims(), g.dims);
}

// The configurable maximum on declared voxel data, compressed or not, named with the numbers.
TEST_F(Hostile, DataPastTheConfiguredLimitIsRefused) {
    scan::ReadLimits limits;
    limits.maxDataBytes = 256;
    test::writeFile(dir / "small.nii", smallNifti());
    expectScanError(dir / "small.nii",
                    "header says 8x8x8 uint8 (512 bytes), more than the limit of 256 bytes of scan "
                    "data",
                    limits);
    test::writeFile(dir / "small.nii.gz", files::gzipBytes(smallNifti()));
    expectScanError(dir / "small.nii.gz", "more than the limit of 256 bytes", limits);
    test::writeFile(dir / "small.nrrd",
                    test::concat("NRRD0004\ntype: uchar\ndimension: 3\nsizes: 8 8 8\nencoding: "
                                 "raw\n\n",
                                 std::vector<std::byte>(512)));
    expectScanError(dir / "small.nrrd", "more than the limit of 256 bytes", limits);
    EXPECT_NO_THROW((void)scan::readScan(dir / "small.nrrd"));
    // The default: 1200^3 float32 (6.4 GiB) is past 4 GiB, refused from the header alone.
    Geometry g;
    g.dims = glm::ivec3(1200);
    test::NiftiOptions o;
    o.datatype = NIFTI_TYPE_FLOAT32;
    test::writeFile(dir / "big.nii.gz", files::gzipBytes(test::niftiFile(g, noise(4096), o)));
    expectScanError(dir / "big.nii.gz",
                    "header says 1200x1200x1200 float32 (6.4 GiB), more than the limit of 4.0 GiB");
    EXPECT_LT(peakRssMiB(), 256.0);
}

// ASCII data holds a number per two characters at most: a few bytes cannot claim a gigavoxel.
TEST_F(Hostile, AsciiDataClaimingMoreNumbersThanItHolds) {
    test::writeFile(dir / "ascii.nrrd",
                    std::string("NRRD0004\ntype: float\ndimension: 3\nsizes: 1000 1000 100\n"
                                "encoding: ascii\n\n1 2 3 4\n"));
    expectScanError(dir / "ascii.nrrd", "but 8 bytes of ascii data hold at most 5 numbers");
    EXPECT_LT(peakRssMiB(), 256.0);
}

// A rescale that is not finite, or that takes the stored range past float32, is refused with
// the fields named. (nifticlib reads a NaN slope as "no scaling": wrong units without a word.)
TEST_F(Hostile, NiftiRescaleNotFiniteOrPastFloat) {
    test::NiftiOptions o;
    o.slope = std::numeric_limits<double>::quiet_NaN();
    test::writeFile(dir / "nan_slope.nii", smallNifti(o));
    expectScanError(dir / "nan_slope.nii", "rescale (scl_slope/scl_inter) refused: slope is nan");
    o.slope = 2.0;
    o.inter = std::numeric_limits<double>::infinity();
    test::writeFile(dir / "inf_inter.nii", smallNifti(o));
    expectScanError(dir / "inf_inter.nii", "refused: intercept is inf");
    // The pattern's largest stored value is 77: 77e37 is past float32's 3.4e38.
    o.inter = 0.0;
    o.slope = 1e37;
    test::writeFile(dir / "big_slope.nii", smallNifti(o));
    expectScanError(dir / "big_slope.nii", "take stored 77 to 7.7e+38, beyond float32's range");
    o.slope = -1e37;
    test::writeFile(dir / "neg_slope.nii", smallNifti(o));
    expectScanError(dir / "neg_slope.nii", "beyond float32's range");
    // NIfTI-2 keeps a double intercept: 1e300 is finite but no float.
    o.version = 2;
    o.slope = 1.0;
    o.inter = 1e300;
    test::writeFile(dir / "big_inter.nii", smallNifti(o));
    expectScanError(dir / "big_inter.nii", "take stored 0 to 1e+300, beyond float32's range");
    // Within range it reads; slope 0 means no scaling whatever the intercept.
    o.version = 1;
    o.slope = 1e36;
    o.inter = 0.0;
    test::writeFile(dir / "ok.nii", smallNifti(o));
    EXPECT_FLOAT_EQ(static_cast<float>(scan::readScan(dir / "ok.nii").volume.stats().max), 77e36F);
    o.slope = 0.0;
    o.inter = std::numeric_limits<double>::quiet_NaN();
    test::writeFile(dir / "none.nii", smallNifti(o));
    EXPECT_EQ(scan::readScan(dir / "none.nii").volume.rescale().slope, 1.0);
}

TEST_F(Hostile, HeaderDataSizeMismatch) {
    test::writeFile(
        dir / "short.nrrd",
        test::concat("NRRD0004\ntype: short\ndimension: 3\nsizes: 10 10 10\nencoding: raw\n\n",
                     std::vector<std::byte>(1000)));
    expectScanError(dir / "short.nrrd",
                    "header says 10x10x10 int16 (2.0 KiB) but the file holds only 1000 bytes");
    test::writeFile(
        dir / "short.mha",
        test::concat(
            "NDims = 3\nDimSize = 4 4 4\nElementType = MET_USHORT\nElementDataFile = LOCAL\n",
            std::vector<std::byte>(100)));
    expectScanError(dir / "short.mha", "but the file holds only 100 bytes");
    auto mgh = test::mghFile(test::obliqueGeometry({4, 4, 4}), 3, test::patternValues({4, 4, 4}));
    mgh.resize(mgh.size() - 10);
    test::writeFile(dir / "short.mgz", files::gzipBytes(mgh));
    expectScanError(dir / "short.mgz", "but the data ends after");
}

TEST_F(Hostile, NanVoxelInFloatData) {
    const Geometry g = test::obliqueGeometry({4, 4, 4});
    auto values = test::patternValues(g.dims);
    values[1 + 4 * 2 + 16 * 3] = std::numeric_limits<double>::quiet_NaN();
    test::NiftiOptions o;
    o.datatype = NIFTI_TYPE_FLOAT32;
    test::writeFile(dir / "nan.nii", test::niftiFile(g, test::encodeSamples(values, "float32"), o));
    expectScanError(dir / "nan.nii", "1 voxels are NaN or infinite (first at 1,2,3)");
    values[0] = 1e300; // float64 past float range
    o.datatype = NIFTI_TYPE_FLOAT64;
    test::writeFile(dir / "inf.nii", test::niftiFile(g, test::encodeSamples(values, "float64"), o));
    expectScanError(dir / "inf.nii", "2 voxels are NaN or infinite (first at 0,0,0)");
}

TEST_F(Hostile, EmptyFolderAndEmptyFile) {
    std::filesystem::create_directory(dir / "empty");
    expectScanError(dir / "empty", "the folder is empty");
    test::writeFile(dir / "empty.nii", std::string());
    expectScanError(dir / "empty.nii", "the file is empty");
    test::writeFile(dir / "empty.nrrd", std::string());
    expectScanError(dir / "empty.nrrd", "the file is empty");
}

TEST_F(Hostile, NonImageFileWithScanExtension) {
    std::string text;
    for (int n = 0; n < 20; ++n) {
        text += "This is a text file, not a scan.\n"; // longer than any binary header
    }
    const std::pair<const char*, const char*> cases[] = {
        {"text.nii", "not a NIfTI file"},        {"text.nii.gz", "not a NIfTI file"},
        {"text.nrrd", "not a NRRD file"},        {"text.mha", "not a MetaImage header"},
        {"text.mgz", "not an MGH/MGZ file"},     {"text.tif", "cannot read as an image"},
        {"text.png", "cannot read as an image"},
    };
    for (const auto& [name, problem] : cases) {
        test::writeFile(dir / name, text);
        expectScanError(dir / name, problem);
    }
    std::filesystem::create_directory(dir / "folder");
    test::writeFile(dir / "folder" / "a.png", text);
    try {
        (void)scan::readScan(dir / "folder");
        ADD_FAILURE() << "a folder with a fake image was read";
    } catch (const scan::ScanError& e) {
        EXPECT_NE(std::string(e.what()).find("a.png: cannot read as an image"), std::string::npos)
            << e.what();
    }
}

TEST_F(Hostile, NrrdWithMissingFields) {
    test::writeFile(dir / "nosizes.nrrd",
                    std::string("NRRD0004\ntype: uint8\ndimension: 3\nencoding: raw\n\n"));
    expectScanError(dir / "nosizes.nrrd", "NRRD header has no \"sizes\" field");
    test::writeFile(
        dir / "noend.nrrd",
        std::string("NRRD0004\ntype: uint8\ndimension: 3\nsizes: 1 1 1\nencoding: raw\n"));
    expectScanError(dir / "noend.nrrd", "no blank line ends it");
    test::writeFile(dir / "nodata.nhdr",
                    std::string("NRRD0004\ntype: uint8\ndimension: 3\nsizes: 1 1 1\nencoding: "
                                "raw\ndata file: missing.raw\n"));
    expectScanError(dir / "nodata.nhdr", "data file");
    test::writeFile(dir / "dev.nhdr", std::string("NRRD0004\ntype: uint8\ndimension: 3\nsizes: 9 9 "
                                                  "9\nencoding: raw\ndata file: /dev/zero\n"));
    expectScanError(dir / "dev.nhdr", "not a regular file");
    test::writeFile(dir / "vec.nrrd",
                    std::string("NRRD0004\ntype: uint8\ndimension: 3\nsizes: 3 2 2\nspace: RAS\n"
                                "space directions: none (1,0,0) (0,1,0)\nencoding: raw\n\n"));
    expectScanError(dir / "vec.nrrd", "NRRD axis 0 is not spatial");
}

TEST_F(Hostile, ImageStackWithMixedSizes) {
    for (const auto& [name, w] : {std::pair{"a1.png", 4}, std::pair{"a2.png", 5}}) {
        auto out = OIIO::ImageOutput::create((dir / name).string());
        ASSERT_TRUE(out);
        ASSERT_TRUE(
            out->open((dir / name).string(), OIIO::ImageSpec(w, 3, 1, OIIO::TypeDesc::UINT8)));
        const std::vector<std::uint8_t> pixels(static_cast<std::size_t>(w * 3), 9);
        ASSERT_TRUE(out->write_image(OIIO::TypeDesc::UINT8, pixels.data()));
        out->close();
    }
    try {
        (void)scan::readScan(dir);
        ADD_FAILURE() << "mixed sizes were read";
    } catch (const scan::ScanError& e) {
        EXPECT_NE(
            std::string(e.what()).find("a2.png: is 5x3 with 1 channels but the first slice is 4x3"),
            std::string::npos)
            << e.what();
    }
}

// OpenImageIO decodes a whole page at its declared size: the stack is bounded before that.
TEST_F(Hostile, ImageStackPastTheConfiguredLimitIsRefused) {
    std::filesystem::create_directory(dir / "stack");
    for (const char* name : {"s1.png", "s2.png"}) {
        const auto file = (dir / "stack" / name).string();
        auto out = OIIO::ImageOutput::create(file);
        ASSERT_TRUE(out);
        ASSERT_TRUE(out->open(file, OIIO::ImageSpec(16, 16, 1, OIIO::TypeDesc::UINT8)));
        const std::vector<std::uint8_t> pixels(256, 9);
        ASSERT_TRUE(out->write_image(OIIO::TypeDesc::UINT8, pixels.data()));
        out->close();
    }
    scan::ReadLimits limits;
    limits.maxDataBytes = 500;
    expectScanError(dir / "stack",
                    "the images make 16x16x2 uint8 (512 bytes), more than the limit of 500 bytes",
                    limits);
    EXPECT_EQ(scan::readScan(dir / "stack").volume.dims(), glm::ivec3(16, 16, 2));
}

TEST_F(Hostile, FourDimensionalNiftiIsRefused) {
    test::NiftiOptions o;
    o.volumes = 3;
    const Geometry g = test::obliqueGeometry({2, 2, 2});
    test::writeFile(dir / "4d.nii", test::niftiFile(g, std::vector<std::byte>(24), o));
    expectScanError(dir / "4d.nii", "holds 3 volumes (4D or more)");
}

TEST_F(Hostile, VoxOffsetPastTheEnd) {
    auto bytes = smallNifti();
    float far = 1e9f;
    std::memcpy(bytes.data() + 108, &far, 4);
    test::writeFile(dir / "far.nii", bytes);
    expectScanError(dir / "far.nii", "lies beyond the end of the file");
    far = std::numeric_limits<float>::quiet_NaN();
    std::memcpy(bytes.data() + 108, &far, 4);
    test::writeFile(dir / "nan.nii", bytes);
    expectScanError(dir / "nan.nii", "does not point past the header");
}

TEST_F(Hostile, ShearedOrDegenerateGeometry) {
    Geometry g = test::obliqueGeometry({2, 2, 2});
    test::NiftiOptions o;
    o.qformCode = 0;
    auto bytes = test::niftiFile(g, std::vector<std::byte>(8), o);
    float shear = 0.9f; // srow_x[1]: j gains an x component, no longer orthogonal to i
    std::memcpy(bytes.data() + 280 + 4, &shear, 4);
    test::writeFile(dir / "shear.nii", bytes);
    expectScanError(dir / "shear.nii", "sform is sheared");
    test::writeFile(dir / "zero.nrrd",
                    std::string("NRRD0004\ntype: uint8\ndimension: 3\nsizes: 1 1 1\nspace: LPS\n"
                                "space directions: (0,0,0) (0,1,0) (0,0,1)\nencoding: raw\n\nX"));
    expectScanError(dir / "zero.nrrd", "is not positive and finite");
}

} // namespace
} // namespace steerseg::test
