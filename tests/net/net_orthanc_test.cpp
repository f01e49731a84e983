// `steerseg send` against a real PACS: Orthanc on loopback ports, checked through its REST API.
// The DICOM SEG comes from `steerseg export` on a real CT series and must arrive filed with the
// source's study and frame of reference, every frame pointing at a source instance Orthanc holds.
#include "exports/mask_writer.hpp"
#include "net/net_harness.hpp"
#include "scan/dicom_source.hpp"
#include "scan/scan_reader.hpp"
#include "support/cli_run.hpp"
#include "support/test_data.hpp"

#include <algorithm>
#include <fstream>
#include <gtest/gtest.h>
#include <set>

namespace steerseg::test {
namespace {

namespace fs = std::filesystem;

std::size_t countLines(const std::string& text, const std::string& prefix) {
    std::size_t n = 0;
    for (std::size_t at = 0; at < text.size();) {
        const std::size_t end = text.find('\n', at);
        n += text.compare(at, prefix.size(), prefix) == 0 ? 1 : 0;
        at = end == std::string::npos ? text.size() : end + 1;
    }
    return n;
}

std::string sendTo(const OrthancServer& pacs, const std::string& files) {
    return "send --host 127.0.0.1 --port " + std::to_string(pacs.dicomPort()) +
           " --called-aet ORTHANC --aet STEERSEG " + files;
}

// `steerseg export` of a ball in the middle of the scan (some slices with frames, some without)
// as <dir>/seg.dcm, with `extra` options.
CliRun exportSeg(const fs::path& dir, const fs::path& series, const scan::LoadedScan& scan,
                 const std::string& extra) {
    const Geometry& g = scan.volume.geometry();
    std::vector<std::uint8_t> mask(g.voxelCount());
    for (int k = 0; k < g.dims.z; ++k) {
        for (int j = 0; j < g.dims.y; ++j) {
            for (int i = 0; i < g.dims.x; ++i) {
                const glm::dvec3 d = glm::dvec3(i, j, k) - glm::dvec3(g.dims) / 2.0;
                mask[linearIndex(g.dims, i, j, k)] = glm::length(d) < 12.0 ? 1 : 0;
            }
        }
    }
    exports::writeMask(dir / "mask.nii.gz", g, mask);
    return runSteerseg("export --input " + series.string() + " --mask " +
                       (dir / "mask.nii.gz").string() + " --output " + (dir / "seg.dcm").string() +
                       extra);
}

TEST(NetOrthanc, ExportedSegArrivesWithItsSourceStudyAndFrames) {
    STEERSEG_REQUIRE_DATA(series, "lung-ct-ibsi/dicom/image");
    STEERSEG_REQUIRE_PROGRAM(OrthancServer::kProgram, "orthanc");
    const fs::path dir = tempDir("net-orthanc-seg");
    const scan::LoadedScan scan = scan::readScan(series);
    ASSERT_NE(scan.dicom, nullptr);
    const CliRun exported = exportSeg(dir, series, scan, "");
    ASSERT_EQ(exported.exitCode, 0) << exported.err;

    OrthancServer pacs(dir);
    std::string files;
    for (const auto& entry : fs::directory_iterator(series)) {
        files += entry.path().string() + " ";
    }
    files += (dir / "seg.dcm").string();
    const CliRun sent = runSteerseg(sendTo(pacs, files));
    ASSERT_EQ(sent.exitCode, 0) << sent.out << sent.err;
    const std::size_t objects = scan.dicom->slices.size() + 1;
    EXPECT_EQ(countLines(sent.out, "accepted "), objects) << sent.out;

    const nlohmann::json instances = pacs.get("/instances?expand");
    ASSERT_EQ(instances.size(), objects);
    std::set<std::string> held;
    std::string segId;
    for (const auto& instance : instances) {
        held.insert(instance.at("MainDicomTags").at("SOPInstanceUID").get<std::string>());
    }
    for (const auto& instance : instances) {
        const nlohmann::json tags =
            pacs.get("/instances/" + instance.at("ID").get<std::string>() + "/simplified-tags");
        if (!tags.contains("Modality") || tags.at("Modality") != "SEG") {
            continue;
        }
        segId = instance.at("ID");
        EXPECT_EQ(tags.at("StudyInstanceUID"), scan.dicom->studyInstanceUid);
        EXPECT_EQ(tags.at("FrameOfReferenceUID"), scan.dicom->frameOfReferenceUid);
        EXPECT_NE(tags.at("SeriesInstanceUID"), scan.dicom->seriesInstanceUid);
        EXPECT_EQ(tags.at("ReferencedSeriesSequence").at(0).at("SeriesInstanceUID"),
                  scan.dicom->seriesInstanceUid);
        const auto& frames = tags.at("PerFrameFunctionalGroupsSequence");
        ASSERT_FALSE(frames.empty());
        for (const auto& frame : frames) {
            const std::string source = frame.at("DerivationImageSequence")
                                           .at(0)
                                           .at("SourceImageSequence")
                                           .at(0)
                                           .at("ReferencedSOPInstanceUID");
            EXPECT_TRUE(held.count(source) == 1) << source << " is not in Orthanc";
        }
    }
    EXPECT_FALSE(segId.empty()) << "no SEG among Orthanc's instances";
    // Filed under the source's study: one study, two series.
    const nlohmann::json studies = pacs.get("/studies?expand");
    ASSERT_EQ(studies.size(), 1u);
    EXPECT_EQ(studies[0].at("Series").size(), 2u);
    fs::remove_all(dir);
}

TEST(NetOrthanc, RefusedConnectionsAndRejectedAssociationsFailEachFileOnItsLine) {
    STEERSEG_REQUIRE_DATA(series, "lung-ct-ibsi/dicom/image");
    STEERSEG_REQUIRE_PROGRAM(OrthancServer::kProgram, "orthanc");
    const fs::path dir = tempDir("net-orthanc-refused");
    const std::string one = (series / "DCM_IMG_00000.dcm").string();
    const std::string two = (series / "DCM_IMG_00001.dcm").string();

    const CliRun nobody = runSteerseg("send --host 127.0.0.1 --port " + std::to_string(freePort()) +
                                      " --called-aet PACS " + one + " " + two);
    EXPECT_EQ(nobody.exitCode, 1);
    EXPECT_EQ(countLines(nobody.out, "failed "), 2u) << nobody.out;
    EXPECT_NE(nobody.out.find("connection refused"), std::string::npos) << nobody.out;
    EXPECT_NE(nobody.err.find("2 of 2 object(s) not accepted"), std::string::npos) << nobody.err;

    OrthancServer pacs(dir);
    const CliRun wrongAe =
        runSteerseg("send --host 127.0.0.1 --port " + std::to_string(pacs.dicomPort()) +
                    " --called-aet NOTORTHANC " + one);
    EXPECT_EQ(wrongAe.exitCode, 1);
    EXPECT_NE(wrongAe.out.find("association rejected"), std::string::npos) << wrongAe.out;

    // A file that is not DICOM fails alone; the good one next to it still goes.
    std::ofstream(dir / "notes.txt") << "not a DICOM file\n";
    const CliRun mixed = runSteerseg(sendTo(pacs, one + " " + (dir / "notes.txt").string()));
    EXPECT_EQ(mixed.exitCode, 1);
    EXPECT_EQ(countLines(mixed.out, "accepted "), 1u) << mixed.out;
    EXPECT_NE(mixed.out.find("notes.txt: cannot be read as DICOM"), std::string::npos) << mixed.out;
    EXPECT_EQ(pacs.get("/instances").size(), 1u);

    const CliRun usage = runSteerseg("send --to pacs " + one);
    EXPECT_EQ(usage.exitCode, 2);
    EXPECT_NE(usage.err.find("no [[dicom.peers]] named 'pacs'"), std::string::npos) << usage.err;
    fs::remove_all(dir);
}

// `steerseg export --send`: written first, then through the outbox; with the PACS down it waits
// there (the export itself succeeds) and `send --outbox` delivers it once the PACS is back.
TEST(NetOrthanc, ExportSendsItsSegThroughTheOutbox) {
    STEERSEG_REQUIRE_DATA(series, "lung-ct-ibsi/dicom/image");
    STEERSEG_REQUIRE_PROGRAM(OrthancServer::kProgram, "orthanc");
    const fs::path dir = tempDir("net-orthanc-export-send");
    const scan::LoadedScan scan = scan::readScan(series);
    OrthancServer pacs(dir);
    const fs::path config = dir / "node.toml";
    std::ofstream(config) << "[audit]\npath = \"" << (dir / "audit.jsonl").string()
                          << "\"\n[dicom]\noutbox = \"" << (dir / "outbox").string()
                          << "\"\nretry_first_seconds = 0.2\n[[dicom.peers]]\nname = \"pacs\"\n"
                             "aet = \"ORTHANC\"\nhost = \"127.0.0.1\"\nsend = true\nport = "
                          << pacs.dicomPort() << "\n";
    const std::string send = " --send pacs --config " + config.string();

    const CliRun delivered = exportSeg(dir, series, scan, send);
    ASSERT_EQ(delivered.exitCode, 0) << delivered.err;
    const auto report = nlohmann::json::parse(delivered.out);
    EXPECT_TRUE(report.at("delivered").get<bool>()) << delivered.out;
    EXPECT_TRUE(report.contains("measurement_report_outbox_id")) << delivered.out;
    // The SEG and its measurement report (docs/exports.md) go together.
    EXPECT_EQ(pacs.get("/instances").size(), 2u);

    pacs.stop();
    const CliRun waiting = exportSeg(dir, series, scan, send);
    ASSERT_EQ(waiting.exitCode, 0) << waiting.err;
    const auto queued = nlohmann::json::parse(waiting.out);
    EXPECT_FALSE(queued.at("delivered").get<bool>());
    EXPECT_NE(queued.at("waiting_because").get<std::string>().find("connection refused"),
              std::string::npos)
        << waiting.out;
    pacs.start();
    const CliRun drained = runSteerseg("send --outbox --wait 10 --config " + config.string());
    EXPECT_EQ(drained.exitCode, 0) << drained.out << drained.err;
    // The second export is a new SEG and report (new UIDs): four instances, each once.
    EXPECT_EQ(pacs.get("/instances").size(), 4u);

    const CliRun notSeg = runSteerseg("export --input " + series.string() + " --mask " +
                                      (dir / "mask.nii.gz").string() + " --output " +
                                      (dir / "m.nii.gz").string() + send);
    EXPECT_EQ(notSeg.exitCode, 2);
    EXPECT_NE(notSeg.err.find("only a DICOM SEG"), std::string::npos) << notSeg.err;
    fs::remove_all(dir);
}

} // namespace
} // namespace steerseg::test
