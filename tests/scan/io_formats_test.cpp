// NRRD, MetaImage, MGH/MGZ and image stacks: files written here from a known volume on an
// oblique grid, read back and compared; plus the real NRRD masks in the shared data.
#include "files/file_write.hpp"
#include "scan/nrrd_header.hpp"
#include "scan/scan_reader.hpp"
#include "support/io_test_files.hpp"
#include "support/test_data.hpp"

#include <OpenImageIO/imageio.h>
#include <bit>
#include <charconv>
#include <cmath>
#include <gtest/gtest.h>
#include <zlib.h>

namespace steerseg::test {
namespace {

using test::pattern;

void expectPattern(const Volume& v) {
    const auto d = v.dims();
    for (int k = 0; k < d.z; ++k) {
        for (int j = 0; j < d.y; ++j) {
            for (int i = 0; i < d.x; ++i) {
                ASSERT_EQ(v.valueAt(i, j, k), pattern(i, j, k)) << i << "," << j << "," << k;
            }
        }
    }
}

std::string num(double v) {
    char buf[32];
    const auto r = std::to_chars(buf, buf + sizeof buf, v);
    return {buf, r.ptr};
}

std::string vec(const glm::dvec3& v) {
    return "(" + num(v.x) + "," + num(v.y) + "," + num(v.z) + ")";
}

std::string nums(const glm::dvec3& v) {
    return num(v.x) + " " + num(v.y) + " " + num(v.z);
}

// NRRD header lines for `g`, with space directions given in `space` (RAS flips x and y).
std::string nrrdFields(const Geometry& g, const std::string& type,
                       const std::string& space = "LPS") {
    const glm::dvec3 flip = space == "RAS" ? glm::dvec3(-1, -1, 1) : glm::dvec3(1);
    std::string h = "type: " + type + "\ndimension: 3\nspace: " +
                    (space == "RAS" ? "right-anterior-superior" : "left-posterior-superior") + "\n";
    h += "sizes: " + std::to_string(g.dims.x) + " " + std::to_string(g.dims.y) + " " +
         std::to_string(g.dims.z) + "\n";
    h += "space directions: " + vec(flip * g.direction[0] * g.spacing[0]) + " " +
         vec(flip * g.direction[1] * g.spacing[1]) + " " +
         vec(flip * g.direction[2] * g.spacing[2]) + "\n";
    h += "space origin: " + vec(flip * g.origin) + "\n";
    return h;
}

const glm::ivec3 kDims(6, 5, 4);

TEST(NrrdReader, AttachedRawGzipAsciiBothEndians) {
    const Geometry g = test::obliqueGeometry(kDims);
    const auto values = test::patternValues(kDims);
    const auto dir = test::tempDir("nrrd-attached");
    struct Case {
        const char* name;
        std::string header;
        std::vector<std::byte> data;
    };
    std::string ascii;
    for (const double v : values) {
        ascii += num(v) + (ascii.size() % 7 == 0 ? "\n" : " ");
    }
    const Case cases[] = {
        {"raw.nrrd", nrrdFields(g, "short") + "encoding: raw\nendian: little\n",
         test::encodeSamples(values, "int16")},
        {"big.nrrd", nrrdFields(g, "uint16", "RAS") + "encoding: raw\nendian: big\n",
         test::encodeSamples(values, "uint16", true)},
        {"gz.nrrd", nrrdFields(g, "float") + "encoding: gzip\nendian: little\n",
         files::gzipBytes(test::encodeSamples(values, "float32"))},
        {"dbl.nrrd", nrrdFields(g, "double") + "encoding: gz\nendian: big\n",
         files::gzipBytes(test::encodeSamples(values, "float64", true))},
        {"ascii.nrrd", nrrdFields(g, "unsigned char") + "encoding: ascii\n",
         test::concat(ascii, {})},
    };
    for (const Case& c : cases) {
        SCOPED_TRACE(c.name);
        test::writeFile(dir / c.name,
                        test::concat("NRRD0004\n# comment\n" + c.header + "\n", c.data));
        const scan::LoadedScan scan = scan::readScan(dir / c.name);
        EXPECT_EQ(scan.format, "nrrd");
        test::expectSameGeometry(scan.volume.geometry(), g, 1e-9);
        expectPattern(scan.volume);
    }
}

// .nhdr + detached data, with line skip and byte skip in front of the data.
TEST(NrrdReader, DetachedHeaderWithSkips) {
    const Geometry g = test::obliqueGeometry(kDims);
    const auto values = test::patternValues(kDims);
    const auto dir = test::tempDir("nrrd-detached");
    test::writeFile(dir / "vol.raw",
                    test::concat("junk line\nmore\nXYZ", test::encodeSamples(values, "int32")));
    test::writeFile(
        dir / "vol.nhdr",
        "NRRD0005\n" + nrrdFields(g, "int") +
            "encoding: raw\nendian: little\ndata file: vol.raw\nline skip: 2\nbyte skip: 3\n");
    const scan::LoadedScan scan = scan::readScan(dir / "vol.nhdr");
    test::expectSameGeometry(scan.volume.geometry(), g, 1e-9);
    EXPECT_EQ(scan.volume.type(), VoxelType::Float32);
    expectPattern(scan.volume);

    // byte skip -1: the data is the end of the file.
    test::writeFile(dir / "tail.nhdr",
                    "NRRD0004\n" + nrrdFields(g, "int") +
                        "encoding: raw\nendian: little\ndata file: vol.raw\nbyte skip: -1\n");
    expectPattern(scan::readScan(dir / "tail.nhdr").volume);
}

// A 2D NRRD is one slice; spacings without space directions give an axis-aligned grid.
TEST(NrrdReader, TwoDimensionalWithSpacings) {
    const auto dir = test::tempDir("nrrd-2d");
    const auto values = test::patternValues({4, 3, 1});
    test::writeFile(
        dir / "s.nrrd",
        test::concat(
            "NRRD0001\ntype: uchar\ndimension: 2\nsizes: 4 3\nspacings: 0.5 nan\nencoding: raw\n\n",
            test::encodeSamples(values, "uint8")));
    const Volume v = scan::readScan(dir / "s.nrrd").volume;
    EXPECT_EQ(v.dims(), glm::ivec3(4, 3, 1));
    EXPECT_EQ(v.geometry().spacing, glm::dvec3(0.5, 1.0, 1.0));
    EXPECT_EQ(v.geometry().direction, glm::dmat3(1.0));
    expectPattern(v);
}

// The header parser works on text alone (fuzz targets call it so).
TEST(NrrdReader, ParserReportsHeaderEnd) {
    const std::string text =
        "NRRD0004\ntype: uint8\ndimension: 3\nsizes: 2 2 2\nencoding: raw\n\nDATA";
    const scan::RawDataSpec spec = scan::parseNrrdHeader("t.nrrd", text, true, {});
    EXPECT_EQ(spec.headerBytes, text.size() - 4);
    EXPECT_EQ(spec.geometry.dims, glm::ivec3(2));
}

// Brain.nrrd (LPS, its own grid with i and j flipped) and the same mask resampled on the MR
// grid (NIfTI, RAS) must sit in the same place in the world.
TEST(NrrdReader, RealMaskMatchesNiftiMaskInWorld) {
    STEERSEG_REQUIRE_DATA(nrrd, "head-mr-seg3d/Brain.nrrd");
    STEERSEG_REQUIRE_DATA(nifti, "head-mr-seg3d/seg3d_brain_mask_on_MR.nii.gz");
    const Volume a = scan::readScan(nrrd).volume;
    const Volume b = scan::readScan(nifti).volume;
    EXPECT_EQ(a.dims(), glm::ivec3(160, 232, 160));
    const glm::dvec3 d = test::worldCentroid(a) - test::worldCentroid(b);
    EXPECT_LT(glm::length(d), 2.0) << d.x << " " << d.y << " " << d.z;
    // The grids differ (flipped axes), so the agreement is not a trivial one.
    EXPECT_GT(glm::length(a.geometry().origin - b.geometry().origin), 10.0);
}

std::string mhaFields(const Geometry& g, const std::string& type) {
    std::string h = "ObjectType = Image\nNDims = 3\nBinaryData = True\n";
    h += "TransformMatrix =";
    for (int c = 0; c < 3; ++c) {
        h += " " + nums(g.direction[c]); // ITK: the direction of i, then j, then k
    }
    h += "\nOffset = " + nums(g.origin) +
         "\nCenterOfRotation = 0 0 0\nAnatomicalOrientation = RAI\n";
    h += "ElementSpacing = " + nums(g.spacing) + "\n";
    h += "DimSize = " + std::to_string(g.dims.x) + " " + std::to_string(g.dims.y) + " " +
         std::to_string(g.dims.z) + "\n";
    h += "ElementType = " + type + "\n";
    return h;
}

TEST(MetaImageReader, LocalRawCompressedAndDetachedBigEndian) {
    const Geometry g = test::obliqueGeometry(kDims);
    const auto values = test::patternValues(kDims);
    const auto dir = test::tempDir("metaimage");
    test::writeFile(dir / "raw.mha",
                    test::concat(mhaFields(g, "MET_SHORT") +
                                     "BinaryDataByteOrderMSB = False\nElementDataFile = LOCAL\n",
                                 test::encodeSamples(values, "int16")));
    // MetaImage "CompressedData" is a zlib stream (not gzip).
    const auto floats = test::encodeSamples(values, "float32");
    std::vector<std::byte> z(compressBound(static_cast<uLong>(floats.size())));
    uLongf zsize = static_cast<uLongf>(z.size());
    ASSERT_EQ(compress2(reinterpret_cast<Bytef*>(z.data()), &zsize,
                        reinterpret_cast<const Bytef*>(floats.data()),
                        static_cast<uLong>(floats.size()), 6),
              Z_OK);
    z.resize(zsize);
    test::writeFile(dir / "z.mha",
                    test::concat(mhaFields(g, "MET_FLOAT") +
                                     "CompressedData = True\nCompressedDataSize = " +
                                     std::to_string(zsize) + "\nElementDataFile = LOCAL\n",
                                 z));
    test::writeFile(dir / "d.raw",
                    test::concat("PADDING!", test::encodeSamples(values, "uint16", true)));
    test::writeFile(dir / "d.mhd",
                    mhaFields(g, "MET_USHORT") +
                        "ElementByteOrderMSB = True\nHeaderSize = 8\nElementDataFile = d.raw\n");
    for (const char* name : {"raw.mha", "z.mha", "d.mhd"}) {
        SCOPED_TRACE(name);
        const scan::LoadedScan scan = scan::readScan(dir / name);
        EXPECT_EQ(scan.format, "metaimage");
        test::expectSameGeometry(scan.volume.geometry(), g, 1e-9);
        expectPattern(scan.volume);
    }
}

// ITK's TransformMatrix lists the axis directions in turn; a non-symmetric matrix tells the
// order apart from its transpose.
TEST(MetaImageReader, TransformMatrixIsAxisDirectionsInTurn) {
    const auto dir = test::tempDir("metaimage-dir");
    test::writeFile(dir / "r.mha",
                    test::concat("NDims = 3\nDimSize = 2 2 2\nElementType = MET_UCHAR\n"
                                 "TransformMatrix = 0 1 0 -1 0 0 0 0 1\nElementDataFile = LOCAL\n",
                                 std::vector<std::byte>(8)));
    const Geometry g = scan::readScan(dir / "r.mha").volume.geometry();
    EXPECT_EQ(g.direction[0], glm::dvec3(0, 1, 0));  // i runs along +y (posterior)
    EXPECT_EQ(g.direction[1], glm::dvec3(-1, 0, 0)); // j runs along -x
}

TEST(MgzReader, MghAndMgzOnObliqueGrid) {
    const Geometry g = test::obliqueGeometry(kDims);
    const auto values = test::patternValues(kDims);
    const auto dir = test::tempDir("mgz");
    const int types[] = {0, 1, 3, 4};
    for (const int type : types) {
        SCOPED_TRACE(type);
        const auto mgh = test::mghFile(g, type, values);
        test::writeFile(dir / "v.mgh", mgh);
        test::writeFile(dir / "v.mgz", files::gzipBytes(mgh));
        for (const char* name : {"v.mgh", "v.mgz"}) {
            const scan::LoadedScan scan = scan::readScan(dir / name);
            EXPECT_EQ(scan.format, "mgz");
            test::expectSameGeometry(scan.volume.geometry(), g);
            expectPattern(scan.volume);
        }
    }
}

// Voxel (dims/2) sits at c_ras: FreeSurfer's centre convention, checked without our writer.
TEST(MgzReader, CentreConvention) {
    std::vector<std::byte> h(284);
    const auto put32 = [&](std::size_t at, std::uint32_t v) {
        for (int b = 0; b < 4; ++b) {
            h[at + static_cast<std::size_t>(b)] = static_cast<std::byte>(v >> (24 - 8 * b));
        }
    };
    const auto putF = [&](std::size_t at, float f) { put32(at, std::bit_cast<std::uint32_t>(f)); };
    put32(0, 1);
    put32(4, 4);
    put32(8, 6);
    put32(12, 8);
    put32(16, 1);
    put32(20, 0);
    h[29] = std::byte{1}; // goodRASflag
    putF(30, 1.0f);
    putF(34, 2.0f);
    putF(38, 3.0f);
    // Mdc identity in RAS; c_ras = (10, 20, 30).
    putF(42, 1.0f);
    putF(58, 1.0f);
    putF(74, 1.0f);
    putF(78, 10.0f);
    putF(82, 20.0f);
    putF(86, 30.0f);
    h.resize(284 + 4 * 6 * 8);
    const auto dir = test::tempDir("mgz-centre");
    test::writeFile(dir / "c.mgh", h);
    const Geometry g = scan::readScan(dir / "c.mgh").volume.geometry();
    const glm::dvec3 centre = g.indexToWorld(glm::dvec3(2, 3, 4));
    EXPECT_NEAR(centre.x, -10.0, 1e-9); // LPS
    EXPECT_NEAR(centre.y, -20.0, 1e-9);
    EXPECT_NEAR(centre.z, 30.0, 1e-9);
    EXPECT_EQ(g.spacing, glm::dvec3(1, 2, 3));
}

void writeImage(const std::filesystem::path& file, int w, int h, int channels,
                const std::vector<std::uint8_t>& pixels) {
    auto out = OIIO::ImageOutput::create(file.string());
    ASSERT_TRUE(out);
    const OIIO::ImageSpec spec(w, h, channels, OIIO::TypeDesc::UINT8);
    ASSERT_TRUE(out->open(file.string(), spec));
    ASSERT_TRUE(out->write_image(OIIO::TypeDesc::UINT8, pixels.data()));
    out->close();
}

std::vector<std::uint8_t> slicePixels(int w, int h, int k) {
    std::vector<std::uint8_t> p;
    for (int j = 0; j < h; ++j) {
        for (int i = 0; i < w; ++i) {
            p.push_back(static_cast<std::uint8_t>(pattern(i, j, k)));
        }
    }
    return p;
}

// Slices sort naturally (s2 before s10), whatever the directory order.
TEST(ImageStackReader, FolderOfPngsInNaturalOrder) {
    const auto dir = test::tempDir("stack-png");
    const int w = 7;
    const int h = 5;
    for (int k = 0; k < 12; ++k) {
        writeImage(dir / ("s" + std::to_string(k) + ".png"), w, h, 1, slicePixels(w, h, k));
    }
    test::writeFile(dir / "notes.txt", std::string("not an image"));
    const scan::LoadedScan scan = scan::readScan(dir);
    EXPECT_EQ(scan.format, "image-stack");
    EXPECT_EQ(scan.volume.type(), VoxelType::UInt8);
    EXPECT_EQ(scan.volume.dims(), glm::ivec3(w, h, 12));
    EXPECT_EQ(scan.volume.geometry().spacing, glm::dvec3(1.0));
    expectPattern(scan.volume);
}

TEST(ImageStackReader, RgbBecomesLuminance) {
    const auto dir = test::tempDir("stack-rgb");
    writeImage(dir / "a.png", 2, 1, 3, {255, 0, 0, 0, 0, 255});
    const Volume v = scan::readScan(dir).volume;
    EXPECT_EQ(v.valueAt(0, 0, 0), std::round(0.2126 * 255));
    EXPECT_EQ(v.valueAt(1, 0, 0), std::round(0.0722 * 255));
}

TEST(ImageStackReader, MultiPageTiff) {
    const auto dir = test::tempDir("stack-tiff");
    const auto file = dir / "pages.tif";
    const int w = 6;
    const int h = 4;
    const int pages = 3;
    auto out = OIIO::ImageOutput::create(file.string());
    ASSERT_TRUE(out);
    ASSERT_TRUE(out->supports("multiimage"));
    std::vector<OIIO::ImageSpec> specs(pages, OIIO::ImageSpec(w, h, 1, OIIO::TypeDesc::UINT16));
    ASSERT_TRUE(out->open(file.string(), pages, specs.data()));
    for (int k = 0; k < pages; ++k) {
        if (k > 0) {
            ASSERT_TRUE(out->open(file.string(), specs[static_cast<std::size_t>(k)],
                                  OIIO::ImageOutput::AppendSubimage));
        }
        std::vector<std::uint16_t> p;
        for (const auto v : slicePixels(w, h, k)) {
            p.push_back(v);
        }
        ASSERT_TRUE(out->write_image(OIIO::TypeDesc::UINT16, p.data()));
    }
    out->close();
    const scan::LoadedScan scan = scan::readScan(file);
    EXPECT_EQ(scan.volume.type(), VoxelType::UInt16);
    EXPECT_EQ(scan.volume.dims(), glm::ivec3(w, h, pages));
    expectPattern(scan.volume);
}

} // namespace
} // namespace steerseg::test
