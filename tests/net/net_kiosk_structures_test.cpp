// Several structures in one kiosk session, end to end (docs/structures.md): a scripted kiosk
// (offscreen) segments the liver, the spleen and the stomach of the abdominal CT series (its 20
// slices hold no kidney),
// each from its box, exports one DICOM SEG with its measurement report and a NIfTI label map,
// and its outbox sends the SEG and the SR to a real Orthanc. The SEG read back with pydicom
// holds three segments, each equal voxel for voxel to its label in the label map; dciodvfy finds
// no error in either object; the report's figures are `steerseg measure`'s on the label map.
#include "core/volume.hpp"
#include "net/net_harness.hpp"
#include "scan/scan_reader.hpp"
#include "support/cli_run.hpp"
#include "support/report_reader.hpp"
#include "support/test_data.hpp"

#include <fstream>
#include <gtest/gtest.h>
#include <map>
#include <set>
#include <sstream>

namespace steerseg::test {
namespace {

namespace fs = std::filesystem;

struct Organ {
    const char* name;
    int label; // in TotalSegmentator's labels
};
// The stomach is no site structure of the shipped config: free text, coded as tissue.
constexpr std::array<Organ, 3> kOrgans{{{"Liver", 5}, {"Spleen", 1}, {"Stomach", 6}}};

// Each organ's bounding box in the series' voxel indices, from the reference labels (whose j
// axis runs the other way: through world coordinates).
std::map<int, std::pair<glm::ivec3, glm::ivec3>> boxesOf(const fs::path& series,
                                                         const fs::path& labels) {
    const Geometry g = scan::readScan(series).volume.geometry();
    const Volume ref = scan::readScan(labels).volume;
    std::map<int, std::pair<glm::ivec3, glm::ivec3>> out;
    const glm::ivec3 d = ref.dims();
    for (int k = 0; k < d.z; ++k) {
        for (int j = 0; j < d.y; ++j) {
            for (int i = 0; i < d.x; ++i) {
                const int label = static_cast<int>(ref.storedAt(ref.linearIndex(i, j, k)));
                if (label != 5 && label != 1 && label != 6) {
                    continue;
                }
                const glm::ivec3 at(
                    glm::round(g.worldToIndex(ref.geometry().indexToWorld(glm::dvec3(i, j, k)))));
                auto [it, fresh] = out.try_emplace(label, at, at);
                it->second.first = glm::min(it->second.first, at);
                it->second.second = glm::max(it->second.second, at);
            }
        }
    }
    return out;
}

// The TotalSegmentator series is anonymised down to no study, series, instance or frame of
// reference UID, which a series from a PACS always has and a SEG must reference: a copy of it
// gets them (dcmodify leaves the JPEG 2000 pixel data as it is).
fs::path withUids(const fs::path& series, const fs::path& dir) {
    const fs::path copy = dir / "series";
    fs::create_directories(copy);
    const std::string root = "1.2.826.0.1.3680043.10.1099.49.";
    for (const auto& f : fs::directory_iterator(series)) {
        const fs::path target = copy / f.path().filename();
        fs::copy_file(f.path(), target);
        const std::string name = f.path().filename().string(); // CT.<its media storage UID>
        const ShellRun r = runShell(
            "/usr/bin/dcmodify -nb -i \"(0020,000d)=" + root + "1\" -i \"(0020,000e)=" + root +
            "2\" -i \"(0020,0052)=" + root + "3\" -i \"(0008,0016)=1.2.840.10008.5.1.4.1.1.2\" " +
            "-i \"(0008,0018)=" + name.substr(name.find('.') + 1) + "\" " + shellQuoted(target));
        EXPECT_EQ(r.status, 0) << r.output;
    }
    return copy;
}

std::string quoted(const std::string& name) {
    return "\"" + name + "\"";
}

TEST(NetKioskStructures, ThreeOrgansGoToThePacsAsOneSegAndOneReport) {
    STEERSEG_REQUIRE_DATA(anonymised, "abdomen-ct-totalseg/example_ct_dicom");
    STEERSEG_REQUIRE_DATA(labels, "abdomen-ct-totalseg/example_seg_dicom.nii.gz");
    STEERSEG_REQUIRE_PROGRAM(OrthancServer::kProgram, "orthanc");
    STEERSEG_REQUIRE_PROGRAM("/usr/bin/dciodvfy", "dicom3tools");
    STEERSEG_REQUIRE_PROGRAM("/usr/bin/dcmodify", "dcmtk");
    const fs::path dir = tempDir("net-kiosk-structures");
    const fs::path series = withUids(anonymised, dir);
    OrthancServer pacs(dir);
    const fs::path out = dir / "steerseg-export";
    std::ofstream(dir / "kiosk.toml")
        << "[export]\nfolder = \"" << out.string() << "\"\nformats = [\"dcm\", \"nii.gz\"]\n"
        << "[audit]\npath = \"" << (dir / "audit.jsonl").string() << "\"\n[autosave]\nfolder = \""
        << (dir / "autosave").string() << "\"\n[dicom]\nenabled = true\nport = " << freePort()
        << "\nstore = \"" << (dir / "store").string() << "\"\noutbox = \""
        << (dir / "outbox").string() << "\"\nmin_free_mb = 0\n"
        << "[[dicom.peers]]\nname = \"pacs\"\naet = \"ORTHANC\"\nhost = \"127.0.0.1\"\n"
           "send = true\nport = "
        << pacs.dicomPort() << "\n";

    const auto boxes = boxesOf(series, labels);
    std::ostringstream script;
    // Reading the abdominal CT takes over a minute under ASan beside another test on 2 cores.
    script << "load " << series.string() << "\nwait loaded timeout 240\n";
    for (const Organ& organ : kOrgans) {
        const auto& [lo, hi] = boxes.at(organ.label);
        script << "structure add " << quoted(organ.name) << "\nbox " << lo.x << ' ' << lo.y << ' '
               << lo.z << ' ' << hi.x << ' ' << hi.y << ' ' << hi.z
               << "\nrun\nwait state paused timeout 240\n";
    }
    script << "structure delete \"Segment 1\"\nexpect structures == 3\nfinish\n"
              "wait state review\nexport\nwait state done timeout 120\n"
              "wait until outbox == 0 timeout 60\n";
    std::ofstream(dir / "organs.session") << script.str();

    ChildProcess kiosk({steersegBinary().string(), "kiosk", "--allow-root", "--platform",
                        "offscreen", "--size", "320x240", "--max-seconds", "900", "--no-resume",
                        "--config", (dir / "kiosk.toml").string(), "--script",
                        (dir / "organs.session").string()},
                       dir / "kiosk.log");
    ASSERT_TRUE(waitUntil([&] { return !kiosk.running(); }, std::chrono::seconds(960)))
        << kiosk.log();
    const std::string log = kiosk.log();
    ASSERT_EQ(log.find("organs.session:"), std::string::npos) << log; // no step failed

    fs::path seg;
    fs::path labelMap;
    for (const auto& f : fs::directory_iterator(out)) {
        const std::string name = f.path().filename().string();
        if (name.ends_with(".dcm") && !name.ends_with(".sr.dcm")) {
            seg = f.path();
        } else if (name.ends_with(".nii.gz")) {
            labelMap = f.path();
        }
    }
    ASSERT_FALSE(seg.empty()) << log;
    ASSERT_FALSE(labelMap.empty()) << log;
    const fs::path report = seg.parent_path() / (seg.stem().string() + ".sr.dcm");
    ASSERT_TRUE(fs::exists(report));
    ASSERT_TRUE(fs::exists(out / (labelMap.stem().stem().string() + ".label.txt")));

    // Orthanc holds the SEG and the SR, in the series' study.
    const std::string study = scan::readScan(series).dicom->studyInstanceUid;
    std::set<std::string> modalities;
    for (const auto& instance : pacs.get("/instances?expand")) {
        const nlohmann::json tags =
            pacs.get("/instances/" + instance.at("ID").get<std::string>() + "/simplified-tags");
        modalities.insert(tags.at("Modality").get<std::string>());
        EXPECT_EQ(tags.at("StudyInstanceUID"), study);
    }
    EXPECT_EQ(modalities, (std::set<std::string>{"SEG", "SR"}));
    expectDciodvfyValid(seg, "Segmentation");
    expectDciodvfyValid(report, "EnhancedSR");

    // The SEG's segments, voxel for voxel the label map's labels 1..3 in the session's order.
    const Volume map = scan::readScan(labelMap).volume;
    std::map<int, std::vector<std::size_t>> labelled;
    for (std::size_t v = 0; v < map.geometry().voxelCount(); ++v) {
        if (const auto label = static_cast<int>(map.storedAt(v)); label != 0) {
            labelled[label].push_back(v);
        }
    }
    const ShellRun read = runShell(
        "/usr/bin/python3 " +
        shellQuoted(fs::path(STEERSEG_SOURCE_DIR) / "tests" / "exports" / "read_structure_seg.py") +
        " " + shellQuoted(seg) + " " + shellQuoted(series));
    ASSERT_EQ(read.status, 0) << read.output;
    std::istringstream lines(read.output);
    std::map<int, std::string> names;
    std::map<int, std::vector<std::size_t>> segmented;
    for (std::string line; std::getline(lines, line);) {
        std::vector<std::string> w;
        std::istringstream in(line);
        for (std::string word; std::getline(in, word, '\t');) {
            w.push_back(word);
        }
        if (w.size() >= 3 && w[0] == "segment") {
            names[std::stoi(w[1])] = w[2];
        } else if (w.size() >= 3 && w[0] == "voxels") {
            auto& v = segmented[std::stoi(w[1])];
            for (std::size_t i = 3; i < w.size(); ++i) {
                v.push_back(std::stoull(w[i]));
            }
        }
    }
    ASSERT_EQ(names.size(), 3U) << read.output.substr(0, 2000);
    const auto report_ = readReport(report);
    EXPECT_EQ(report_.count("group"), 3U);
    const glm::dvec3 s = map.geometry().spacing;
    const double diagonal = std::sqrt(s.x * s.x + s.y * s.y + s.z * s.z);
    for (int n = 1; n <= 3; ++n) {
        SCOPED_TRACE(kOrgans[static_cast<std::size_t>(n - 1)].name);
        EXPECT_EQ(names[n], kOrgans[static_cast<std::size_t>(n - 1)].name);
        ASSERT_FALSE(labelled[n].empty());
        EXPECT_EQ(segmented[n], labelled[n]) << "segment " << n << " against label " << n;
        const CliRun measured =
            runSteerseg("measure --input " + series.string() + " --mask " + labelMap.string() +
                        " --label " + std::to_string(n) + " --json");
        ASSERT_EQ(measured.exitCode, 0) << measured.err;
        const nlohmann::json m = nlohmann::json::parse(measured.out);
        const std::map<std::string, Num> nums = numsOf(report_, std::to_string(n));
        ASSERT_TRUE(nums.contains("118565006 -"));
        const double volume = m["volume_ml"].get<double>();
        EXPECT_NEAR(nums.at("118565006 -").fp, volume, 1e-3 * volume);
        EXPECT_NEAR(nums.at("103339001 -").fp, m["axial"]["longest"]["length_mm"].get<double>(),
                    diagonal);
        EXPECT_NEAR(nums.at("103340004 -").fp,
                    m["axial"]["perpendicular"]["length_mm"].get<double>(), diagonal);
        EXPECT_NEAR(nums.at("81827009 56851009").fp, m["longest_3d"]["length_mm"].get<double>(),
                    diagonal);
    }
    // dsrdump (DCMTK) reads the same document: a group per structure.
    const ShellRun dump = runShell("/usr/bin/dsrdump " + shellQuoted(report));
    EXPECT_EQ(dump.status, 0) << dump.output;
    std::size_t groups = 0;
    for (auto at = dump.output.find("Measurement Group"); at != std::string::npos;
         at = dump.output.find("Measurement Group", at + 1)) {
        ++groups;
    }
    EXPECT_GE(groups, 3U) << dump.output;
    // The audit names the structure each action steered.
    const std::string audit = readText(dir / "audit.jsonl");
    for (const Organ& organ : kOrgans) {
        EXPECT_NE(audit.find("\"structure\":\"" + std::string(organ.name) + "\""),
                  std::string::npos);
    }
}

} // namespace
} // namespace steerseg::test
