// The DICOM SR Measurement Report (TID 1500) written beside a DICOM SEG: a synthetic CT series
// and a mask whose figures `steerseg measure --json` gives are exported with `steerseg export`;
// the report must pass dciodvfy, hold in dsrdump and in an independent reader (pydicom,
// tests/tools/read_measurement_report.py) the very figures of `measure`, and reference the SEG
// written beside it. Two segments make two groups; an empty mask makes neither file.
#include "core/mask_measurements.hpp"
#include "exports/dicom_seg_writer.hpp"
#include "exports/mask_writer.hpp"
#include "exports/measurement_report.hpp"
#include "scan/scan_reader.hpp"
#include "support/cli_run.hpp"
#include "support/report_reader.hpp"
#include "support/test_data.hpp"
#include "synthetic_ct_series.hpp"

#include <cmath>
#include <cstdio>
#include <dcmtk/dcmdata/dcdeftag.h>
#include <dcmtk/dcmdata/dcfilefo.h>
#include <dcmtk/dcmdata/dcuid.h>
#include <gtest/gtest.h>
#include <map>
#include <nlohmann/json.hpp>
#include <sstream>
#include <sys/wait.h>

namespace steerseg::test {

namespace fs = std::filesystem;

namespace {

// An ellipsoid (semi-axes 6 x 5 mm in-plane, 7 mm across slices) off the grid's centre.
std::vector<std::uint8_t> ellipsoid(const Geometry& g, const glm::dvec3& centreIndex,
                                    const glm::dvec3& semiAxesMm) {
    std::vector<std::uint8_t> mask(g.voxelCount(), 0);
    for (int k = 0; k < g.dims.z; ++k) {
        for (int j = 0; j < g.dims.y; ++j) {
            for (int i = 0; i < g.dims.x; ++i) {
                const glm::dvec3 d = (glm::dvec3(i, j, k) - centreIndex) * g.spacing / semiAxesMm;
                mask[linearIndex(g.dims, i, j, k)] = glm::dot(d, d) <= 1.0 ? 1 : 0;
            }
        }
    }
    return mask;
}

std::string sopInstanceOf(const fs::path& file) {
    DcmFileFormat f;
    EXPECT_TRUE(f.loadFile(file.c_str()).good());
    OFString value;
    f.getDataset()->findAndGetOFString(DCM_SOPInstanceUID, value);
    return value.c_str();
}

// Each figure of `steerseg measure --json` against the report's group 1: equal, since both come
// from core/mask_measurements (the DS within its 16 characters, the floating point exactly).
void expectFiguresOf(const nlohmann::json& m, const std::map<std::string, Num>& nums) {
    const auto expect = [&](const std::string& key, const std::string& unit, double want) {
        const auto it = nums.find(key);
        ASSERT_NE(it, nums.end()) << key;
        EXPECT_EQ(it->second.unit, unit) << key;
        EXPECT_DOUBLE_EQ(it->second.fp, want) << key;
        EXPECT_NEAR(it->second.ds, want, 1e-9 * std::max(1.0, std::abs(want))) << key;
    };
    expect("118565006 -", "ml", m["volume_ml"].get<double>());
    expect("C0JK -", "mm2", m["surface_area_mm2"].get<double>());
    expect("103339001 -", "mm", m["axial"]["longest"]["length_mm"].get<double>());
    expect("103340004 -", "mm", m["axial"]["perpendicular"]["length_mm"].get<double>());
    expect("81827009 56851009", "mm", m["longest_3d"]["length_mm"].get<double>());
    expect("112031 373098007", "[hnsf'U]", m["intensity"]["mean"].get<double>());
    expect("112031 386136009", "[hnsf'U]", m["intensity"]["sd"].get<double>());
    expect("112031 255605001", "[hnsf'U]", m["intensity"]["min"].get<double>());
    expect("112031 56851009", "[hnsf'U]", m["intensity"]["max"].get<double>());
    EXPECT_EQ(nums.size(), 9U);
}

// The figure dsrdump prints for a concept (its first NUM of that meaning).
double dsrdumpValue(const std::string& dump, const std::string& meaning) {
    const std::string key = ",\"" + meaning + "\")=\"";
    const std::size_t at = dump.find(key);
    if (at == std::string::npos) {
        ADD_FAILURE() << "dsrdump shows no " << meaning << "\n" << dump;
        return NAN;
    }
    return std::stod(dump.substr(at + key.size()));
}

} // namespace

TEST(MeasurementReport, ExportWritesItBesideTheSegWithMeasuresFigures) {
    const fs::path dir = tempDir("sr-export");
    const fs::path series = dir / "series";
    fs::create_directories(series);
    const std::string seriesUid = writeSeries(series);
    const scan::LoadedScan scan = scan::readScan(series);
    ASSERT_NE(scan.dicom, nullptr);
    const Geometry& g = scan.volume.geometry();
    const std::vector<std::uint8_t> mask = ellipsoid(g, {11.3, 9.6, 4.4}, {6.0, 5.0, 7.0});
    exports::writeMask(dir / "mask.nii.gz", g, mask);

    const CliRun measured = runSteerseg("measure --input " + series.string() + " --mask " +
                                        (dir / "mask.nii.gz").string() + " --json");
    ASSERT_EQ(measured.exitCode, 0) << measured.err;
    const nlohmann::json m = nlohmann::json::parse(measured.out);

    const fs::path seg = dir / "out" / "lesion.dcm";
    fs::create_directories(seg.parent_path());
    const CliRun exported = runSteerseg("export --input " + series.string() + " --mask " +
                                        (dir / "mask.nii.gz").string() + " --output " +
                                        seg.string() + " --segment-name Lesion");
    ASSERT_EQ(exported.exitCode, 0) << exported.err;
    const fs::path report = dir / "out" / "lesion.sr.dcm";
    EXPECT_EQ(nlohmann::json::parse(exported.out)["measurement_report"], report.string());
    ASSERT_TRUE(fs::exists(report));

    expectDciodvfyValid(report, "EnhancedSR");
    const auto r = readReport(report);
    const auto header = r.find("header");
    ASSERT_NE(header, r.end());
    EXPECT_EQ(header->second[0], "1.2.840.10008.5.1.4.1.1.88.22"); // Enhanced SR
    EXPECT_EQ(header->second[1], "SR");
    EXPECT_EQ(header->second[2], scan.dicom->studyInstanceUid);
    EXPECT_NE(header->second[3], seriesUid); // a series of its own
    EXPECT_EQ(header->second[4], "SR-TEST-1");
    EXPECT_EQ(header->second[5], "1500");
    ASSERT_EQ(r.count("group"), 1U);
    const std::vector<std::string>& group = r.find("group")->second;
    EXPECT_EQ(group[1], "Lesion");
    EXPECT_EQ(group[2], "85756007"); // the SEG's Segmented Property Type
    EXPECT_EQ(group[3], sopInstanceOf(seg));
    EXPECT_EQ(group[4], "1");
    EXPECT_EQ(group[5], seriesUid);
    std::map<std::string, std::string> observers;
    const auto [from, to] = r.equal_range("observer");
    for (auto it = from; it != to; ++it) {
        observers[it->second[0]] = it->second[1];
    }
    EXPECT_EQ(observers["person"], "Operator");
    EXPECT_EQ(observers["device"], exports::applianceDeviceUid());
    expectFiguresOf(m, numsOf(r, "1"));

    // dsrdump (DCMTK) reads the same document and shows the same figures.
    const ShellRun dump = runShell("/usr/bin/dsrdump " + shellQuoted(report));
    EXPECT_EQ(dump.status, 0) << dump.output;
    EXPECT_NEAR(dsrdumpValue(dump.output, "Volume"), m["volume_ml"].get<double>(),
                1e-6 * m["volume_ml"].get<double>());
    EXPECT_NEAR(dsrdumpValue(dump.output, "Long Axis"),
                m["axial"]["longest"]["length_mm"].get<double>(), 1e-6);
    EXPECT_NEAR(dsrdumpValue(dump.output, "Short Axis"),
                m["axial"]["perpendicular"]["length_mm"].get<double>(), 1e-6);
    EXPECT_NEAR(dsrdumpValue(dump.output, "Diameter"), m["longest_3d"]["length_mm"].get<double>(),
                1e-6);
    EXPECT_NEAR(dsrdumpValue(dump.output, "Surface area of mesh"),
                m["surface_area_mm2"].get<double>(), 1e-6 * m["surface_area_mm2"].get<double>());
}

// Several segments make several groups, each referencing its own segment number: the report
// needs no change for a multi-structure session.
TEST(MeasurementReport, OneGroupPerSegment) {
    const fs::path dir = tempDir("sr-two");
    const fs::path series = dir / "series";
    fs::create_directories(series);
    writeSeries(series);
    const scan::LoadedScan scan = scan::readScan(series);
    const Geometry& g = scan.volume.geometry();
    const std::vector<std::uint8_t> a = ellipsoid(g, {6.0, 6.0, 3.0}, {3.0, 3.0, 4.0});
    const std::vector<std::uint8_t> b = ellipsoid(g, {16.0, 13.0, 6.0}, {4.0, 3.0, 5.0});
    const exports::SegInstance seg =
        exports::writeDicomSeg(dir / "seg.dcm", g, a, scan.dicom.get());
    std::vector<exports::ReportedSegment> segments(2);
    segments[0].number = 1;
    segments[0].label = "First";
    segments[0].measurements = measureMask(scan.volume, a);
    segments[1].number = 2;
    segments[1].label = "Second";
    segments[1].finding = exports::kCodeMass;
    segments[1].site = exports::SegmentCode{"39607008", "SCT", "Lung"};
    segments[1].measurements = measureMask(scan.volume, b);
    const fs::path report = dir / "seg.sr.dcm";
    exports::writeMeasurementReport(report, *scan.dicom, seg, segments);
    expectDciodvfyValid(report, "EnhancedSR");
    const auto r = readReport(report);
    ASSERT_EQ(r.count("group"), 2U);
    auto it = r.find("group");
    EXPECT_EQ(it->second[1], "First");
    EXPECT_EQ(it->second[4], "1");
    ++it;
    EXPECT_EQ(it->second[1], "Second");
    EXPECT_EQ(it->second[2], "4147007");
    EXPECT_EQ(it->second[3], seg.sopInstanceUid);
    EXPECT_EQ(it->second[4], "2");
    EXPECT_DOUBLE_EQ(numsOf(r, "2").at("118565006 -").fp, segments[1].measurements.volumeMl);
    EXPECT_DOUBLE_EQ(numsOf(r, "1").at("118565006 -").fp, segments[0].measurements.volumeMl);
}

TEST(MeasurementReport, RefusesASegmentWithNothingInside) {
    const fs::path dir = tempDir("sr-refuse");
    const fs::path series = dir / "series";
    fs::create_directories(series);
    writeSeries(series);
    const scan::LoadedScan scan = scan::readScan(series);
    const exports::SegInstance seg{UID_SegmentationStorage, uid(), uid(), 1};
    std::vector<exports::ReportedSegment> segments(1); // measured nothing: no voxel
    try {
        exports::writeMeasurementReport(dir / "x.sr.dcm", *scan.dicom, seg, segments);
        FAIL() << "no error";
    } catch (const files::WriteError& e) {
        EXPECT_NE(std::string(e.what()).find("segment 1 has no voxel inside"), std::string::npos)
            << e.what();
    }
    EXPECT_THROW(exports::writeMeasurementReport(dir / "y.sr.dcm", *scan.dicom, seg, {}),
                 files::WriteError);
    EXPECT_FALSE(fs::exists(dir / "x.sr.dcm"));
    EXPECT_FALSE(fs::exists(dir / "y.sr.dcm"));

    // Through the command line an empty mask is refused before either file is written.
    const Geometry& g = scan.volume.geometry();
    exports::writeMask(dir / "empty.nii.gz", g, std::vector<std::uint8_t>(g.voxelCount(), 0));
    const CliRun r =
        runSteerseg("export --input " + series.string() + " --mask " +
                    (dir / "empty.nii.gz").string() + " --output " + (dir / "e.dcm").string());
    EXPECT_NE(r.exitCode, 0);
    EXPECT_NE(r.err.find("the mask is empty"), std::string::npos) << r.err;
    EXPECT_FALSE(fs::exists(dir / "e.dcm"));
    EXPECT_FALSE(fs::exists(dir / "e.sr.dcm"));
}

TEST(MeasurementReport, NameBesideTheSeg) {
    EXPECT_EQ(exports::measurementReportPathFor("/a/b/x.dcm"), fs::path("/a/b/x.sr.dcm"));
    EXPECT_EQ(exports::measurementReportPathFor("/a/seg"), fs::path("/a/seg.sr.dcm"));
    EXPECT_EQ(exports::measurementReportPathFor("X.DCM"), fs::path("X.DCM.sr.dcm"));
    const std::string device = exports::applianceDeviceUid();
    EXPECT_LE(device.size(), 64U);
    EXPECT_EQ(device.find_first_not_of("0123456789."), std::string::npos) << device;
}

// The IBSI lung CT's DICOM series and its GTV: the report holds what `measure` says of them.
TEST(MeasurementReport, RealLungCtGtv) {
    STEERSEG_REQUIRE_DATA(series, "lung-ct-ibsi/dicom/image");
    STEERSEG_REQUIRE_DATA(mask, "lung-ct-ibsi/nifti/mask.nii.gz");
    const fs::path dir = tempDir("sr-lung");
    const CliRun measured =
        runSteerseg("measure --input " + series.string() + " --mask " + mask.string() + " --json");
    ASSERT_EQ(measured.exitCode, 0) << measured.err;
    const nlohmann::json m = nlohmann::json::parse(measured.out);
    const fs::path seg = dir / "gtv.dcm";
    const CliRun exported = runSteerseg("export --input " + series.string() + " --mask " +
                                        mask.string() + " --output " + seg.string());
    ASSERT_EQ(exported.exitCode, 0) << exported.err;
    const fs::path report = dir / "gtv.sr.dcm";
    expectDciodvfyValid(report, "EnhancedSR");
    const auto r = readReport(report);
    ASSERT_EQ(r.count("group"), 1U);
    EXPECT_EQ(r.find("group")->second[3], sopInstanceOf(seg));
    expectFiguresOf(m, numsOf(r, "1"));
}

} // namespace steerseg::test
