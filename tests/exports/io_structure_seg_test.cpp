// Several structures as one DICOM SEG and its measurement report: a synthetic CT series (0.8 x 0.7
// mm pixels, 2 mm slices) and three structures, two of them overlapping, written by
// exports::writeStructures; the SEG and the SR must pass dciodvfy, the SEG read back by pydicom
// alone (read_structure_seg.py) must hold each structure voxel for voxel as its own segment with
// its codes and colour, and the SR one measurement group per segment (dsrdump and pydicom).
#include "core/mask_measurements.hpp"
#include "exports/display_color.hpp"
#include "exports/measurement_report.hpp"
#include "exports/structure_export.hpp"
#include "scan/scan_reader.hpp"
#include "structure_fixture.hpp"
#include "support/cli_run.hpp"
#include "support/report_reader.hpp"
#include "support/test_data.hpp"
#include "synthetic_ct_series.hpp"

#include <cstdio>
#include <dcmtk/dcmdata/dcdeftag.h>
#include <dcmtk/dcmdata/dcfilefo.h>
#include <dcmtk/dcmdata/dcuid.h>
#include <gtest/gtest.h>
#include <map>
#include <sstream>

namespace steerseg::test {

namespace fs = std::filesystem;

namespace {

std::multimap<std::string, std::vector<std::string>> runTool(const fs::path& script,
                                                             const std::string& arguments) {
    const ShellRun r = runShell("/usr/bin/python3 " + shellQuoted(script) + " " + arguments);
    EXPECT_EQ(r.status, 0) << r.output;
    return wordsByLine(r.output);
}

std::vector<std::string> insideIndices(std::span<const std::uint8_t> mask) {
    std::vector<std::string> out;
    for (std::size_t n = 0; n < mask.size(); ++n) {
        if (mask[n] != 0) {
            out.push_back(std::to_string(n));
        }
    }
    return out;
}

std::size_t slicesHolding(std::span<const std::uint8_t> mask) {
    const std::size_t plane = static_cast<std::size_t>(kStructureDims.x) * kStructureDims.y;
    std::size_t slices = 0;
    for (std::size_t at = 0; at < mask.size(); at += plane) {
        const auto slab = mask.subspan(at, plane);
        slices += std::any_of(slab.begin(), slab.end(), [](std::uint8_t v) { return v != 0; });
    }
    return slices;
}

struct Written {
    fs::path dir;
    fs::path series;
    scan::LoadedScan scan;
    StructureMasks masks;
};

Written seriesWithStructures(const std::string& name, bool overlapping) {
    Written w;
    w.dir = tempDir(name);
    w.series = w.dir / "series";
    fs::create_directories(w.series);
    writeSeries(w.series, {"Test^Structures", "STRUCT-1", "20261203", true});
    w.scan = scan::readScan(w.series);
    w.masks = structureMasks(kStructureDims, overlapping);
    return w;
}

} // namespace

TEST(StructureSeg, EveryStructureIsItsOwnSegmentVoxelForVoxel) {
    const Written w = seriesWithStructures("structures-seg", true);
    ASSERT_NE(w.scan.dicom, nullptr);
    const Geometry& g = w.scan.volume.geometry();
    ASSERT_EQ(g.dims, kStructureDims);
    const std::vector<exports::StructureLayer> layers = structureLayers(w.masks);
    const fs::path seg = w.dir / "organs.dcm";
    const exports::ExportSummary summary = exports::writeStructures(
        seg, model::ExportFormat::DicomSeg, {g, layers, w.scan.dicom.get(), &w.scan.volume});
    const fs::path report = w.dir / "organs.sr.dcm";
    ASSERT_EQ(summary.companions, std::vector<fs::path>{report});
    expectDciodvfyValid(seg, "Segmentation");
    expectDciodvfyValid(report, "EnhancedSR");

    const auto r = runTool(fs::path(STEERSEG_SOURCE_DIR) / "tests/exports/read_structure_seg.py",
                           shellQuoted(seg) + " " + shellQuoted(w.series));
    // The colours' CIELab by the published formula (sRGB, D65), computed apart from steerseg.
    const std::vector<std::vector<int>> lab{
        {32689, 45542, 43456}, {39930, 32110, 20859}, {57280, 32239, 54678}};
    ASSERT_EQ(r.count("segment"), 3U);
    auto it = r.find("segment");
    for (std::size_t n = 0; n < 3; ++n, ++it) {
        SCOPED_TRACE(layers[n].segment.name);
        const std::vector<std::string>& s = it->second;
        ASSERT_EQ(s.size(), 9U);
        EXPECT_EQ(s[0], std::to_string(n + 1));
        EXPECT_EQ(s[1], layers[n].segment.name);
        EXPECT_EQ(s[2], layers[n].category.value);
        EXPECT_EQ(s[3], layers[n].type.value);
        EXPECT_EQ(s[4], "SEMIAUTOMATIC");
        EXPECT_EQ(s[5], "steerseg");
        for (int c = 0; c < 3; ++c) {
            EXPECT_NEAR(std::stoi(s[6 + static_cast<std::size_t>(c)]),
                        lab[n][static_cast<std::size_t>(c)], 1);
        }
    }
    const std::vector<std::span<const std::uint8_t>> masks{w.masks.liver, w.masks.spleen,
                                                           w.masks.kidney};
    ASSERT_EQ(r.count("voxels"), 3U);
    it = r.find("voxels");
    auto frames = r.find("frames");
    for (std::size_t n = 0; n < 3; ++n, ++it, ++frames) {
        std::vector<std::string> want{std::to_string(n + 1)};
        const std::vector<std::string> inside = insideIndices(masks[n]);
        want.push_back(std::to_string(inside.size()));
        want.insert(want.end(), inside.begin(), inside.end());
        EXPECT_EQ(it->second, want) << layers[n].segment.name;
        // A frame only where the structure has voxels.
        EXPECT_EQ(frames->second[1], std::to_string(slicesHolding(masks[n])));
    }

    // The report: one group per structure, each naming its own segment of this SEG.
    const auto sr = readReport(report);
    ASSERT_EQ(sr.count("group"), 3U);
    DcmFileFormat segFile;
    ASSERT_TRUE(segFile.loadFile(seg.c_str()).good());
    OFString segUid;
    segFile.getDataset()->findAndGetOFString(DCM_SOPInstanceUID, segUid);
    it = sr.find("group");
    for (std::size_t n = 0; n < 3; ++n, ++it) {
        EXPECT_EQ(it->second[1], layers[n].segment.name);
        EXPECT_EQ(it->second[2], layers[n].type.value);
        EXPECT_EQ(it->second[3], segUid.c_str());
        EXPECT_EQ(it->second[4], std::to_string(n + 1));
    }
    std::map<std::string, double> volumes;
    const auto [from, to] = sr.equal_range("num");
    for (auto num = from; num != to; ++num) {
        if (num->second[1] == "118565006") {
            volumes[num->second[0]] = std::stod(num->second[6]);
        }
    }
    for (std::size_t n = 0; n < 3; ++n) {
        EXPECT_DOUBLE_EQ(volumes[std::to_string(n + 1)],
                         measureMask(w.scan.volume, masks[n]).volumeMl);
    }
    const ShellRun dump = runShell("/usr/bin/dsrdump " + shellQuoted(report));
    EXPECT_EQ(dump.status, 0) << dump.output;
    std::size_t groups = 0;
    for (std::size_t at = dump.output.find("\"Measurement Group\")"); at != std::string::npos;
         at = dump.output.find("\"Measurement Group\")", at + 1)) {
        ++groups;
    }
    EXPECT_EQ(groups, 3U) << dump.output;
    fs::remove_all(w.dir);
}

// A structure with nothing inside cannot be a segment: refused by its name, and neither the SEG
// nor the report is written.
TEST(StructureSeg, RefusesAnEmptyStructureByName) {
    Written w = seriesWithStructures("structures-seg-empty", false);
    std::fill(w.masks.spleen.begin(), w.masks.spleen.end(), 0);
    const fs::path seg = w.dir / "organs.dcm";
    try {
        exports::writeStructures(seg, model::ExportFormat::DicomSeg,
                                 {w.scan.volume.geometry(), structureLayers(w.masks),
                                  w.scan.dicom.get(), &w.scan.volume});
        FAIL() << "no error";
    } catch (const files::WriteError& e) {
        EXPECT_NE(std::string(e.what()).find("the mask is empty for segment 'Spleen'"),
                  std::string::npos)
            << e.what();
    }
    EXPECT_FALSE(fs::exists(seg));
    EXPECT_FALSE(fs::exists(w.dir / "organs.sr.dcm"));
    fs::remove_all(w.dir);
}

// One structure through writeExport: the SEG as before (one segment, the default Tissue codes),
// now with its colour, and the report's one group.
TEST(StructureSeg, OneStructureThroughWriteExport) {
    const Written w = seriesWithStructures("structures-seg-one", false);
    const fs::path seg = w.dir / "liver.dcm";
    const exports::ExportSummary summary = exports::writeExport(
        seg, model::ExportFormat::DicomSeg,
        {w.scan.volume.geometry(), w.masks.liver, {}, {}, w.scan.dicom.get(), &w.scan.volume});
    ASSERT_EQ(summary.companions, std::vector<fs::path>{w.dir / "liver.sr.dcm"});
    expectDciodvfyValid(seg, "Segmentation");
    const auto r = runTool(fs::path(STEERSEG_SOURCE_DIR) / "tests/exports/read_structure_seg.py",
                           shellQuoted(seg) + " " + shellQuoted(w.series));
    ASSERT_EQ(r.count("segment"), 1U);
    const std::vector<std::string>& s = r.find("segment")->second;
    ASSERT_EQ(s.size(), 9U);
    EXPECT_EQ(s[1], "Segment_1");
    EXPECT_EQ(s[2], "85756007");
    EXPECT_EQ(s[3], "85756007");
    // Slicer's first colour (0.945, 0.839, 0.569), by the published formula.
    EXPECT_NEAR(std::stoi(s[6]), 56629, 1);
    EXPECT_NEAR(std::stoi(s[7]), 32905, 1);
    EXPECT_NEAR(std::stoi(s[8]), 42518, 1);
    const std::vector<std::string> inside = insideIndices(w.masks.liver);
    EXPECT_EQ(r.find("voxels")->second.size(), inside.size() + 2);
    fs::remove_all(w.dir);
}

TEST(StructureSeg, DisplayColourAsDicomCieLab) {
    const std::array<std::uint16_t, 3> red = exports::dicomLabFromRgb({1.0, 0.0, 0.0});
    EXPECT_NEAR(red[0], 34891, 1); // L* 53.24, a* 80.09, b* 67.20 (sRGB red under D65)
    EXPECT_NEAR(red[1], 53480, 1);
    EXPECT_NEAR(red[2], 50167, 1);
    const std::array<std::uint16_t, 3> black = exports::dicomLabFromRgb({0.0, 0.0, 0.0});
    EXPECT_EQ(black, (std::array<std::uint16_t, 3>{0, 32896, 32896}));
    const std::array<std::uint16_t, 3> white = exports::dicomLabFromRgb({1.0, 1.0, 1.0});
    EXPECT_EQ(white[0], 65535);
    EXPECT_NEAR(white[1], 32896, 2);
    EXPECT_NEAR(white[2], 32896, 2);
}

} // namespace steerseg::test
