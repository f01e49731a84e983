// DICOM SEG export: series synthesized with DCMTK (axial ascending, stored descending, sagittal,
// oblique, an enhanced multi-frame file) and real series are read by steerseg, a mask written as
// SEG, then validated by dciodvfy and read back by an independent reader
// (tests/tools/read_dicom_seg.py, pydicom).
#include "exports/dicom_seg_writer.hpp"
#include "scan/scan_reader.hpp"
#include "support/cli_run.hpp"
#include "support/test_data.hpp"

#include <array>
#include <cmath>
#include <cstdio>
#include <dcmtk/dcmdata/dcdeftag.h>
#include <dcmtk/dcmdata/dcfilefo.h>
#include <dcmtk/dcmdata/dcuid.h>
#include <fstream>
#include <gtest/gtest.h>
#include <map>
#include <sstream>
#include <sys/wait.h>

namespace steerseg::test {

namespace fs = std::filesystem;

namespace {

struct SeriesSpec {
    int columns = 13; // not a multiple of 8: 1-bit frames then share bytes
    int rows = 11;
    int slices = 7;
    glm::dvec3 rowDirection{1, 0, 0};
    glm::dvec3 columnDirection{0, 1, 0};
    glm::dvec3 origin{-20.5, 14.25, -102.0};
    glm::dvec2 pixelSpacing{0.8, 0.7}; // along i (columns), along j (rows)
    double step = 2.5;
    bool descending = false; // files and instance numbers in descending position
};

struct SourceSlice {
    std::string uid;
    glm::dvec3 position;
};

std::string uid() {
    char text[100];
    return dcmGenerateUniqueIdentifier(text, SITE_INSTANCE_UID_ROOT);
}

std::string decimals(std::initializer_list<double> values) {
    std::string text;
    for (double v : values) {
        char one[32];
        std::snprintf(one, sizeof one, "%.6f", v);
        text += (text.empty() ? "" : "\\") + std::string(one);
    }
    return text;
}

// One CT slice per file. Slice s lies at origin + s * step * normal.
std::vector<SourceSlice> writeSeries(const fs::path& dir, const SeriesSpec& spec) {
    const std::string study = uid();
    const std::string series = uid();
    const std::string frame = uid();
    const glm::dvec3 normal = glm::cross(spec.rowDirection, spec.columnDirection);
    std::vector<SourceSlice> slices;
    for (int n = 0; n < spec.slices; ++n) {
        const int s = spec.descending ? spec.slices - 1 - n : n;
        const glm::dvec3 p = spec.origin + normal * (spec.step * s);
        DcmFileFormat file;
        DcmDataset& d = *file.getDataset();
        const std::string instance = uid();
        d.putAndInsertString(DCM_SOPClassUID, UID_CTImageStorage);
        d.putAndInsertString(DCM_SOPInstanceUID, instance.c_str());
        d.putAndInsertString(DCM_StudyInstanceUID, study.c_str());
        d.putAndInsertString(DCM_SeriesInstanceUID, series.c_str());
        d.putAndInsertString(DCM_FrameOfReferenceUID, frame.c_str());
        d.putAndInsertString(DCM_PositionReferenceIndicator, "");
        d.putAndInsertString(DCM_PatientName, "Test^Phantom");
        d.putAndInsertString(DCM_PatientID, "SEG-TEST-1");
        d.putAndInsertString(DCM_PatientBirthDate, "19700101");
        d.putAndInsertString(DCM_PatientSex, "O");
        d.putAndInsertString(DCM_StudyDate, "20261123");
        d.putAndInsertString(DCM_StudyTime, "101500");
        d.putAndInsertString(DCM_StudyID, "1");
        d.putAndInsertString(DCM_AccessionNumber, "A123");
        d.putAndInsertString(DCM_ReferringPhysicianName, "");
        d.putAndInsertString(DCM_Modality, "CT");
        d.putAndInsertString(DCM_SeriesNumber, "2");
        d.putAndInsertString(DCM_InstanceNumber, std::to_string(n + 1).c_str());
        d.putAndInsertString(DCM_ImageType, "ORIGINAL\\PRIMARY\\AXIAL");
        d.putAndInsertString(DCM_ImagePositionPatient, decimals({p.x, p.y, p.z}).c_str());
        const auto& r = spec.rowDirection;
        const auto& c = spec.columnDirection;
        d.putAndInsertString(DCM_ImageOrientationPatient,
                             decimals({r.x, r.y, r.z, c.x, c.y, c.z}).c_str());
        d.putAndInsertString(DCM_PixelSpacing,
                             decimals({spec.pixelSpacing.y, spec.pixelSpacing.x}).c_str());
        d.putAndInsertString(DCM_SliceThickness, decimals({spec.step}).c_str());
        d.putAndInsertString(DCM_RescaleIntercept, "-1024");
        d.putAndInsertString(DCM_RescaleSlope, "1");
        d.putAndInsertUint16(DCM_SamplesPerPixel, 1);
        d.putAndInsertString(DCM_PhotometricInterpretation, "MONOCHROME2");
        d.putAndInsertUint16(DCM_Rows, static_cast<Uint16>(spec.rows));
        d.putAndInsertUint16(DCM_Columns, static_cast<Uint16>(spec.columns));
        d.putAndInsertUint16(DCM_BitsAllocated, 16);
        d.putAndInsertUint16(DCM_BitsStored, 16);
        d.putAndInsertUint16(DCM_HighBit, 15);
        d.putAndInsertUint16(DCM_PixelRepresentation, 0);
        std::vector<Uint16> pixels(static_cast<std::size_t>(spec.rows * spec.columns));
        for (std::size_t v = 0; v < pixels.size(); ++v) {
            pixels[v] = static_cast<Uint16>(1000 + 10 * s + v % 7);
        }
        d.putAndInsertUint16Array(DCM_PixelData, pixels.data(),
                                  static_cast<unsigned long>(pixels.size()));
        char name[32];
        std::snprintf(name, sizeof name, "im%03d.dcm", n);
        EXPECT_TRUE(file.saveFile((dir / name).c_str(), EXS_LittleEndianExplicit).good());
        slices.push_back({instance, p});
    }
    return slices;
}

// An irregular mask that leaves some slices empty and tells every axis from its mirror image.
std::vector<std::uint8_t> makeMask(const glm::ivec3& dims) {
    std::vector<std::uint8_t> mask(static_cast<std::size_t>(dims.x) * dims.y * dims.z);
    for (int k = 0; k < dims.z; ++k) {
        if (k % 3 == 2) {
            continue;
        }
        for (int j = 0; j < dims.y; ++j) {
            for (int i = 0; i < dims.x; ++i) {
                const bool in = i >= k && j >= 1 && j <= dims.y / 2 + k && (i + 2 * j + k) % 5 != 0;
                mask[linearIndex(dims, i, j, k)] = in ? 1 : 0;
            }
        }
    }
    return mask;
}

// Per source SOP Instance UID, the segmented pixel indices (row * columns + column), as the
// independent reader finds them.
std::map<std::string, std::vector<std::size_t>> readBack(const fs::path& seg,
                                                         const fs::path& sourceDir) {
    const ShellRun r = runShell(
        "/usr/bin/python3 " +
        shellQuoted(fs::path(STEERSEG_SOURCE_DIR) / "tests" / "tools" / "read_dicom_seg.py") + " " +
        shellQuoted(seg) + " " + shellQuoted(sourceDir));
    EXPECT_EQ(r.status, 0) << r.output;
    std::map<std::string, std::vector<std::size_t>> out;
    std::istringstream lines(r.output);
    std::string line;
    while (std::getline(lines, line)) {
        std::istringstream words(line);
        std::string tag;
        std::string instance;
        std::size_t count = 0;
        words >> tag >> instance >> count;
        if (tag != "slice") {
            ADD_FAILURE() << "unexpected reader output: " << line;
            continue;
        }
        auto& v = out[instance];
        for (std::size_t n = 0, index = 0; n < count && words >> index; ++n) {
            v.push_back(index);
        }
        EXPECT_EQ(v.size(), count) << line;
    }
    return out;
}

// What the reader must find: each source slice's segmented pixels, the slice located by the
// test's own knowledge of where it put it (its position), not by steerseg's source record.
std::map<std::string, std::vector<std::size_t>> expected(const Geometry& g,
                                                         const std::vector<std::uint8_t>& mask,
                                                         const std::vector<SourceSlice>& slices) {
    std::map<std::string, std::vector<std::size_t>> out;
    for (const SourceSlice& s : slices) {
        const glm::dvec3 index = g.worldToIndex(s.position);
        EXPECT_NEAR(index.x, 0.0, 1e-3);
        EXPECT_NEAR(index.y, 0.0, 1e-3);
        const int k = static_cast<int>(std::lround(index.z));
        std::vector<std::size_t> pixels;
        for (int j = 0; j < g.dims.y; ++j) {
            for (int i = 0; i < g.dims.x; ++i) {
                if (mask[linearIndex(g.dims, i, j, k)] != 0) {
                    pixels.push_back(static_cast<std::size_t>(j) * g.dims.x + i);
                }
            }
        }
        if (!pixels.empty()) {
            out[s.uid] = std::move(pixels);
        }
    }
    return out;
}

void roundTrip(const std::string& name, const SeriesSpec& spec) {
    const fs::path dir = tempDir("seg-" + name);
    const fs::path source = dir / "series";
    fs::create_directories(source);
    const std::vector<SourceSlice> slices = writeSeries(source, spec);
    const scan::LoadedScan scan = scan::readScan(source);
    ASSERT_NE(scan.dicom, nullptr);
    const Geometry& g = scan.volume.geometry();
    ASSERT_EQ(g.dims, glm::ivec3(spec.columns, spec.rows, spec.slices));
    const std::vector<std::uint8_t> mask = makeMask(g.dims);
    const fs::path seg = dir / "seg.dcm";
    exports::DicomSegOptions options;
    options.label = "Lesion";
    options.category = exports::kCodeMorphologicallyAbnormalStructure;
    options.type = exports::kCodeMass;
    exports::writeDicomSeg(seg, g, mask, scan.dicom.get(), options);
    expectDciodvfyValid(seg, "Segmentation");
    const auto found = readBack(seg, source);
    const auto want = expected(g, mask, slices);
    EXPECT_EQ(found.size(), want.size());
    EXPECT_EQ(found, want);
    fs::remove_all(dir);
}

} // namespace

TEST(DicomSeg, AxialAscending) {
    roundTrip("axial", SeriesSpec{});
}

TEST(DicomSeg, SeriesStoredInDescendingOrder) {
    SeriesSpec spec;
    spec.descending = true;
    roundTrip("descending", spec);
}

TEST(DicomSeg, Sagittal) {
    SeriesSpec spec;
    spec.rowDirection = {0, 1, 0};
    spec.columnDirection = {0, 0, -1};
    spec.columns = 17;
    spec.rows = 9;
    roundTrip("sagittal", spec);
}

TEST(DicomSeg, Oblique) {
    SeriesSpec spec;
    const double a = 0.5235987755982988; // 30 degrees about z, then 20 about x
    const double b = 0.3490658503988659;
    spec.rowDirection = {std::cos(a), std::sin(a), 0};
    const glm::dvec3 col{-std::sin(a), std::cos(a), 0};
    spec.columnDirection = {col.x, col.y * std::cos(b), col.y * std::sin(b)};
    spec.rowDirection = glm::normalize(spec.rowDirection);
    spec.columnDirection =
        glm::normalize(spec.columnDirection -
                       spec.rowDirection * glm::dot(spec.rowDirection, spec.columnDirection));
    roundTrip("oblique", spec);
}

// One enhanced multi-frame file: frames stored at positions 4, 0 and 2 mm along z, described by
// per-frame Plane Position groups; the SEG must reference each by its frame number.
TEST(DicomSeg, EnhancedMultiFrameSource) {
    const fs::path dir = tempDir("seg-multiframe");
    const fs::path source = dir / "series";
    fs::create_directories(source);
    const int columns = 9;
    const int rows = 7;
    const std::array<double, 3> z{4.0, 0.0, 2.0};
    const std::string instance = uid();
    DcmFileFormat file;
    DcmDataset& d = *file.getDataset();
    d.putAndInsertString(DCM_SOPClassUID, UID_EnhancedCTImageStorage);
    d.putAndInsertString(DCM_SOPInstanceUID, instance.c_str());
    d.putAndInsertString(DCM_StudyInstanceUID, uid().c_str());
    d.putAndInsertString(DCM_SeriesInstanceUID, uid().c_str());
    d.putAndInsertString(DCM_FrameOfReferenceUID, uid().c_str());
    d.putAndInsertString(DCM_PatientName, "Test^Multiframe");
    d.putAndInsertString(DCM_PatientID, "SEG-TEST-2");
    d.putAndInsertString(DCM_Modality, "CT");
    d.putAndInsertString(DCM_NumberOfFrames, "3");
    d.putAndInsertUint16(DCM_SamplesPerPixel, 1);
    d.putAndInsertString(DCM_PhotometricInterpretation, "MONOCHROME2");
    d.putAndInsertUint16(DCM_Rows, rows);
    d.putAndInsertUint16(DCM_Columns, columns);
    d.putAndInsertUint16(DCM_BitsAllocated, 16);
    d.putAndInsertUint16(DCM_BitsStored, 16);
    d.putAndInsertUint16(DCM_HighBit, 15);
    d.putAndInsertUint16(DCM_PixelRepresentation, 0);
    DcmItem* shared = nullptr;
    DcmItem* item = nullptr;
    ASSERT_TRUE(d.findOrCreateSequenceItem(DCM_SharedFunctionalGroupsSequence, shared).good());
    ASSERT_TRUE(shared->findOrCreateSequenceItem(DCM_PlaneOrientationSequence, item).good());
    item->putAndInsertString(DCM_ImageOrientationPatient, "1\\0\\0\\0\\1\\0");
    ASSERT_TRUE(shared->findOrCreateSequenceItem(DCM_PixelMeasuresSequence, item).good());
    item->putAndInsertString(DCM_PixelSpacing, "0.5\\0.6");
    item->putAndInsertString(DCM_SliceThickness, "2");
    for (double position : z) {
        DcmItem* frame = nullptr;
        ASSERT_TRUE(
            d.findOrCreateSequenceItem(DCM_PerFrameFunctionalGroupsSequence, frame, -2).good());
        ASSERT_TRUE(frame->findOrCreateSequenceItem(DCM_PlanePositionSequence, item).good());
        item->putAndInsertString(DCM_ImagePositionPatient, decimals({-3.0, 5.0, position}).c_str());
    }
    std::vector<Uint16> pixels(static_cast<std::size_t>(rows * columns * 3), 100);
    d.putAndInsertUint16Array(DCM_PixelData, pixels.data(),
                              static_cast<unsigned long>(pixels.size()));
    ASSERT_TRUE(file.saveFile((source / "mf.dcm").c_str(), EXS_LittleEndianExplicit).good());

    const scan::LoadedScan scan = scan::readScan(source / "mf.dcm");
    ASSERT_NE(scan.dicom, nullptr);
    const Geometry& g = scan.volume.geometry();
    ASSERT_EQ(g.dims, glm::ivec3(columns, rows, 3));
    const std::vector<std::uint8_t> mask = makeMask(g.dims);
    const fs::path seg = dir / "seg.dcm";
    exports::writeDicomSeg(seg, g, mask, scan.dicom.get());
    expectDciodvfyValid(seg, "Segmentation");
    std::vector<SourceSlice> slices;
    for (std::size_t f = 0; f < z.size(); ++f) {
        slices.push_back({instance + ":" + std::to_string(f + 1), {-3.0, 5.0, z[f]}});
    }
    EXPECT_EQ(readBack(seg, source), expected(g, mask, slices));
    fs::remove_all(dir);
}

TEST(DicomSeg, RefusesAScanNotReadFromDicom) {
    Geometry g;
    g.dims = {4, 4, 2};
    const std::vector<std::uint8_t> mask(32, 1);
    try {
        exports::writeDicomSeg(tempDir("seg-nodicom") / "seg.dcm", g, mask, nullptr);
        FAIL() << "no error";
    } catch (const files::WriteError& e) {
        EXPECT_NE(std::string(e.what()).find("DICOM SEG needs a scan read from a DICOM series"),
                  std::string::npos)
            << e.what();
    }
}

TEST(DicomSeg, RefusesAnEmptyMaskAndAMismatchedOne) {
    const fs::path dir = tempDir("seg-refuse");
    fs::create_directories(dir / "series");
    writeSeries(dir / "series", SeriesSpec{});
    const scan::LoadedScan scan = scan::readScan(dir / "series");
    const Geometry& g = scan.volume.geometry();
    const std::vector<std::uint8_t> empty(g.voxelCount(), 0);
    const fs::path seg = dir / "seg.dcm";
    try {
        exports::writeDicomSeg(seg, g, empty, scan.dicom.get());
        FAIL() << "no error";
    } catch (const files::WriteError& e) {
        EXPECT_NE(std::string(e.what()).find("the mask is empty"), std::string::npos) << e.what();
    }
    try {
        exports::writeDicomSeg(seg, g, std::vector<std::uint8_t>(5, 1), scan.dicom.get());
        FAIL() << "no error";
    } catch (const files::WriteError& e) {
        EXPECT_NE(std::string(e.what()).find("the mask has 5 voxels"), std::string::npos)
            << e.what();
    }
    EXPECT_FALSE(fs::exists(seg));
    fs::remove_all(dir);
}

// Real series: a sphere in the middle of the scan, written, validated and read back.
void realRoundTrip(const fs::path& source, const std::string& name) {
    const scan::LoadedScan scan = scan::readScan(source);
    ASSERT_NE(scan.dicom, nullptr);
    const Geometry& g = scan.volume.geometry();
    std::vector<std::uint8_t> mask(g.voxelCount(), 0);
    const glm::dvec3 centre = glm::dvec3(g.dims) * 0.5;
    const double radius = std::min({g.dims.x, g.dims.y, g.dims.z}) * 0.3;
    for (int k = 0; k < g.dims.z; ++k) {
        for (int j = 0; j < g.dims.y; ++j) {
            for (int i = 0; i < g.dims.x; ++i) {
                // Off-centre along i, so a flipped axis would not map onto itself.
                if (glm::length(glm::dvec3(i - 3, j, k) - centre) < radius) {
                    mask[linearIndex(g.dims, i, j, k)] = 1;
                }
            }
        }
    }
    const fs::path dir = tempDir("seg-real-" + name);
    const fs::path seg = dir / "seg.dcm";
    exports::writeDicomSeg(seg, g, mask, scan.dicom.get());
    expectDciodvfyValid(seg, "Segmentation");
    const auto found = readBack(seg, source);
    std::size_t frames = 0;
    for (int k = 0; k < g.dims.z; ++k) {
        std::vector<std::size_t> pixels;
        for (int j = 0; j < g.dims.y; ++j) {
            for (int i = 0; i < g.dims.x; ++i) {
                if (mask[linearIndex(g.dims, i, j, k)] != 0) {
                    pixels.push_back(static_cast<std::size_t>(j) * g.dims.x + i);
                }
            }
        }
        if (pixels.empty()) {
            continue;
        }
        ++frames;
        const auto it = found.find(scan.dicom->slices[static_cast<std::size_t>(k)].sopInstanceUid);
        ASSERT_NE(it, found.end()) << "slice " << k;
        EXPECT_EQ(it->second, pixels) << "slice " << k;
    }
    EXPECT_EQ(found.size(), frames);
    fs::remove_all(dir);
}

TEST(DicomSeg, RealCtSeriesImplicitVr) {
    STEERSEG_REQUIRE_DATA(series, "lung-ct-ibsi/dicom/image");
    realRoundTrip(series, "lung");
}

// TotalSegmentator's example series was anonymized to empty Study, Series, SOP Class and SOP
// Instance UIDs (the meta header keeps the last two): a SEG could not be filed with its study.
TEST(DicomSeg, RefusesARealSeriesWithoutStudyAndSeriesUids) {
    STEERSEG_REQUIRE_DATA(series, "abdomen-ct-totalseg/example_ct_dicom");
    const scan::LoadedScan scan = scan::readScan(series);
    ASSERT_NE(scan.dicom, nullptr);
    EXPECT_FALSE(scan.dicom->slices.front().sopInstanceUid.empty()); // from the meta header
    EXPECT_EQ(scan.dicom->slices.front().sopClassUid, "1.2.840.10008.5.1.4.1.1.2");
    const std::vector<std::uint8_t> mask(scan.volume.geometry().voxelCount(), 1);
    const fs::path seg = tempDir("seg-real-totalseg") / "seg.dcm";
    try {
        exports::writeDicomSeg(seg, scan.volume.geometry(), mask, scan.dicom.get());
        FAIL() << "no error";
    } catch (const files::WriteError& e) {
        EXPECT_NE(std::string(e.what()).find("no StudyInstanceUID or SeriesInstanceUID"),
                  std::string::npos)
            << e.what();
    }
    EXPECT_FALSE(fs::exists(seg));
}

} // namespace steerseg::test
