// The kiosk's PACS search (docs/dicom-network.md "The kiosk's search") end to end: the IBSI lung
// CT stored into Orthanc, then a scripted kiosk (offscreen) searches it by patient ID, retrieves
// it by C-GET with the progress reaching 60 of 60, finds it listed as received, loads it and
// seeds; the audit log has the search, the retrieve and their outcomes. With two query peers
// (a dead one first) a session chooses the second, lists the study's two series there and
// retrieves one of them alone. A peer that accepts the connection and says nothing ends the
// search with one line within the configured timeout.
#include "net/net_harness.hpp"
#include "net/store_scu.hpp"
#include "support/cli_run.hpp"
#include "support/test_data.hpp"

#include <algorithm>
#include <chrono>
#include <fstream>
#include <gtest/gtest.h>
#include <map>
#include <random>
#include <sstream>

namespace steerseg::test {
namespace {

namespace fs = std::filesystem;

// `firstPeer`: a query peer listed before "pacs" (its name and port), so "pacs" is the second.
void writeConfig(const fs::path& dir, int pacsPort, int queryTimeout = 10,
                 const std::pair<std::string, int>& firstPeer = {}) {
    std::ofstream(dir / "kiosk.toml")
        << "[export]\nfolder = \"" << (dir / "export").string() << "\"\n[audit]\npath = \""
        << (dir / "audit.jsonl").string() << "\"\n[autosave]\nfolder = \""
        << (dir / "autosave").string() << "\"\n[dicom]\nenabled = true\nport = " << freePort()
        << "\nstore = \"" << (dir / "store").string() << "\"\noutbox = \""
        << (dir / "outbox").string()
        << "\"\nmin_free_mb = 0\nquery_timeout_seconds = " << queryTimeout
        << "\nsearch_fields = [\"patient_id\", \"study_date\"]\n";
    if (!firstPeer.first.empty()) {
        std::ofstream(dir / "kiosk.toml", std::ios::app)
            << "[[dicom.peers]]\nname = \"" << firstPeer.first
            << "\"\naet = \"ORTHANC\"\nhost = \"127.0.0.1\"\nquery = true\nport = "
            << firstPeer.second << "\n";
    }
    std::ofstream(dir / "kiosk.toml", std::ios::app)
        << "[[dicom.peers]]\nname = \"pacs\"\naet = \"ORTHANC\"\nhost = \"127.0.0.1\"\n"
           "query = true\nport = "
        << pacsPort << "\n";
}

ChildProcess startKiosk(const fs::path& dir, const std::string& session) {
    std::ofstream(dir / "pacs.session") << session;
    return ChildProcess({steersegBinary().string(), "kiosk", "--allow-root", "--platform",
                         "offscreen", "--size", "480x320", "--max-seconds", "120", "--no-resume",
                         "--config", (dir / "kiosk.toml").string(), "--script",
                         (dir / "pacs.session").string(), "--frames", (dir / "frames").string()},
                        dir / "kiosk.log");
}

// Issue 48's loop from the console: a script searches the PACS, retrieves the study by C-GET
// with the progress counted, loads the series, segments it and exports.
TEST(NetKioskPacs, AScriptSearchesRetrievesByCGetLoadsSegmentsAndExports) {
    STEERSEG_REQUIRE_DATA(series, "lung-ct-ibsi/dicom/image");
    STEERSEG_REQUIRE_PROGRAM(OrthancServer::kProgram, "orthanc");
    const fs::path dir = tempDir("net-kiosk-pacs");
    // Orthanc answers C-FIND and C-GET only for a modality it knows.
    OrthancServer pacs(
        dir,
        nlohmann::json{
            {"DicomModalities",
             {{"steerseg", {{"AET", "STEERSEG"}, {"Host", "127.0.0.1"}, {"Port", freePort()}}}}}});
    const std::vector<fs::path> files = filesBelow(series);
    const net::DicomPeer orthanc{OrthancServer::kAet, "127.0.0.1", pacs.dicomPort(), false};
    for (const net::SendOutcome& o : net::sendFiles(orthanc, files, {})) {
        ASSERT_TRUE(o.accepted) << o.file << ": " << o.problem;
    }
    const nlohmann::json patients = pacs.get("/patients?expand");
    ASSERT_EQ(patients.size(), 1U) << patients.dump();
    const std::string patientId =
        patients[0].at("MainDicomTags").at("PatientID").get<std::string>();
    const std::string studyUid =
        pacs.get("/studies?expand")[0].at("MainDicomTags").at("StudyInstanceUID");
    writeConfig(dir, pacs.dicomPort());
    // A search for another patient finds nothing; then the right one, retrieved and loaded.
    ChildProcess kiosk = startKiosk(dir, "search patient_id NOBODY-" + patientId + R"(
wait until searches >= 1 timeout 30
expect found == 0
search patient_id )" + patientId + R"( study_date any
wait until searches >= 2 timeout 30
expect found == 1
retrieve $FOUND
wait until retrieves >= 1 timeout 60
expect retrieved == )" + std::to_string(files.size()) +
                                             R"(
expect retrieve_expected == )" + std::to_string(files.size()) +
                                             R"(
expect retrieve_failed == 0
wait until received >= 1 timeout 30
load $RECEIVED
wait loaded timeout 60
expect state inspect
probe 102 100 30 5
seed 102 100 30 6
expect seeds == 1
run
wait iterations 20 timeout 30
pause
wait state paused
finish
wait state review
export
wait state done timeout 30
expect volume_ml > 0
)");
    ASSERT_TRUE(waitUntil([&] { return !kiosk.running(); }, std::chrono::seconds(130)))
        << kiosk.log();
    const std::string log = kiosk.log();
    EXPECT_EQ(log.find("pacs.session:"), std::string::npos) << log; // no step failed
    EXPECT_EQ(log.find("--max-seconds"), std::string::npos) << log;
    EXPECT_NE(log.find("dicom: 1 study on pacs"), std::string::npos) << log;
    EXPECT_NE(log.find("dicom: retrieved " + std::to_string(files.size()) + " of " +
                       std::to_string(files.size()) + " images from pacs"),
              std::string::npos)
        << log;
    // Every image in the store, in the study's folder: what the load screen listed.
    std::size_t stored = 0;
    for (const fs::path& f : filesBelow(dir / "store" / studyUid)) {
        stored += f.extension() == ".dcm" ? 1 : 0;
    }
    EXPECT_EQ(stored, files.size());
    // The retrieved series segmented and exported: the whole loop from the PACS's search.
    EXPECT_FALSE(filesBelow(dir / "export").empty()) << "nothing exported under " << dir / "export";

    // The actions and the node's records of them in the audit log.
    const fs::path audit = dir / "audit.jsonl";
    const auto queries = auditRecords(audit, "query");
    ASSERT_EQ(queries.size(), 2U);
    EXPECT_EQ(queries[1].at("patient_id"), patientId);
    EXPECT_EQ(queries[1].at("matches"), 1);
    EXPECT_EQ(queries[1].at("problem"), "");
    const auto retrieves = auditRecords(audit, "retrieve");
    ASSERT_EQ(retrieves.size(), 1U);
    EXPECT_EQ(retrieves[0].at("study"), studyUid);
    EXPECT_EQ(retrieves[0].at("method"), "get");
    EXPECT_EQ(retrieves[0].at("received"), files.size());
    EXPECT_EQ(retrieves[0].at("expected"), files.size());
    EXPECT_EQ(retrieves[0].at("problem"), "");
    bool retrieveAction = false;
    for (const nlohmann::json& a : auditRecords(audit, "action")) {
        if (a.value("action", "") == "retrieve_pacs") {
            retrieveAction = true;
            EXPECT_EQ(a.at("values").at("study"), studyUid) << a.dump();
        }
    }
    EXPECT_TRUE(retrieveAction) << readText(audit);
    fs::remove_all(dir);
}

// The study with a second series: three of the lung CT's images under a new series UID
// (number 99, "Copy"), each with a new SOP instance UID, by DCMTK's dcmodify. Returns its UID.
std::string writeSecondSeries(const std::vector<fs::path>& source, const fs::path& folder) {
    fs::create_directories(folder);
    std::mt19937_64 random(std::random_device{}());
    const std::string uid = "2.25." + std::to_string(random() >> 1);
    std::string files;
    for (std::size_t i = 0; i < 3; ++i) {
        const fs::path copy = folder / source.at(i).filename();
        fs::copy_file(source.at(i), copy);
        files += " " + shellQuoted(copy);
    }
    const ShellRun modified = runShell("/usr/bin/dcmodify -nb -gin -i \"(0020,000e)=" + uid +
                                       "\" -i \"(0020,0011)=99\" -i \"(0008,103e)=Copy\"" + files);
    EXPECT_EQ(modified.status, 0) << modified.output;
    return uid;
}

// Issue 48's leftover: two query peers, a dead one first. The first is asked by default and
// fails with a line; a session chooses the second, lists the found study's two series there
// (modality, number, description, images), retrieves the listing's first ($SERIES) alone: only
// that series' files land in the store. A listing on the dead peer ends with its line. The
// audit log has each query with its level.
TEST(NetKioskPacs, TheSecondPeerChosenAStudysSeriesListedAndOneRetrieved) {
    STEERSEG_REQUIRE_DATA(series, "lung-ct-ibsi/dicom/image");
    STEERSEG_REQUIRE_PROGRAM(OrthancServer::kProgram, "orthanc");
    STEERSEG_REQUIRE_PROGRAM("/usr/bin/dcmodify", "dcmtk");
    const fs::path dir = tempDir("net-kiosk-pacs-series");
    OrthancServer pacs(
        dir,
        nlohmann::json{
            {"DicomModalities",
             {{"steerseg", {{"AET", "STEERSEG"}, {"Host", "127.0.0.1"}, {"Port", freePort()}}}}}});
    std::vector<fs::path> files = filesBelow(series);
    std::sort(files.begin(), files.end());
    const std::string copyUid = writeSecondSeries(files, dir / "copy");
    std::vector<fs::path> all = files;
    for (const fs::path& f : filesBelow(dir / "copy")) {
        all.push_back(f);
    }
    const net::DicomPeer orthanc{OrthancServer::kAet, "127.0.0.1", pacs.dicomPort(), false};
    for (const net::SendOutcome& o : net::sendFiles(orthanc, all, {})) {
        ASSERT_TRUE(o.accepted) << o.file << ": " << o.problem;
    }
    const nlohmann::json studies = pacs.get("/studies?expand");
    ASSERT_EQ(studies.size(), 1U) << studies.dump();
    const std::string studyUid = studies[0].at("MainDicomTags").at("StudyInstanceUID");
    const std::string patientId =
        pacs.get("/patients?expand")[0].at("MainDicomTags").at("PatientID").get<std::string>();
    // Each series' UID -> its image count, as Orthanc holds them.
    std::map<std::string, std::size_t> held;
    for (const nlohmann::json& s : pacs.get("/series?expand")) {
        held[s.at("MainDicomTags").at("SeriesInstanceUID")] = s.at("Instances").size();
    }
    ASSERT_EQ(held.size(), 2U);
    ASSERT_EQ(held.at(copyUid), 3U);
    writeConfig(dir, pacs.dicomPort(), 10, {"dead", freePort()});
    ChildProcess kiosk = startKiosk(dir, "search patient_id " + patientId + R"(
wait until searches >= 1 timeout 30
expect found == 0
search peer pacs patient_id )" + patientId + R"(
wait until searches >= 2 timeout 30
expect found == 1
series $FOUND peer pacs
wait until series_listings >= 1 timeout 30
expect listing_series == 0
expect series_found == 2
retrieve $FOUND $SERIES peer pacs
wait until retrieves >= 1 timeout 60
expect retrieve_failed == 0
wait until received >= 1 timeout 30
series $FOUND
wait until series_listings >= 2 timeout 30
expect series_found == 0
)");
    ASSERT_TRUE(waitUntil([&] { return !kiosk.running(); }, std::chrono::seconds(130)))
        << kiosk.log();
    const std::string log = kiosk.log();
    EXPECT_EQ(log.find("pacs.session:"), std::string::npos) << log; // no step failed
    EXPECT_NE(log.find("dicom: search on dead failed: "), std::string::npos) << log;
    EXPECT_NE(log.find("dicom: 1 study on pacs"), std::string::npos) << log;
    EXPECT_NE(log.find("dicom: 2 series of the study on pacs"), std::string::npos) << log;
    EXPECT_NE(log.find("dicom: series of the study on dead failed: "), std::string::npos) << log;

    // The retrieve named one series: that one, whole, and nothing of the other.
    const auto retrieves = auditRecords(dir / "audit.jsonl", "retrieve");
    ASSERT_EQ(retrieves.size(), 1U);
    const std::string fetched = retrieves[0].at("series");
    ASSERT_EQ(held.count(fetched), 1U) << retrieves[0].dump();
    EXPECT_EQ(retrieves[0].at("peer"), "pacs");
    EXPECT_EQ(retrieves[0].at("study"), studyUid);
    EXPECT_EQ(retrieves[0].at("received"), held.at(fetched));
    EXPECT_EQ(retrieves[0].at("problem"), "");
    std::map<std::string, std::size_t> stored; // series folder -> its .dcm files
    for (const fs::path& f : filesBelow(dir / "store")) {
        if (f.extension() == ".dcm") {
            ++stored[f.parent_path().filename().string()];
            EXPECT_EQ(f.parent_path().parent_path().filename(), studyUid) << f;
        }
    }
    EXPECT_EQ(stored, (std::map<std::string, std::size_t>{{fetched, held.at(fetched)}}));

    // Each query in the audit log with its level, peer and outcome.
    const auto queries = auditRecords(dir / "audit.jsonl", "query");
    ASSERT_EQ(queries.size(), 4U);
    EXPECT_EQ(queries[0].at("peer"), "dead");
    EXPECT_NE(queries[0].at("problem"), "");
    EXPECT_EQ(queries[1].at("peer"), "pacs");
    EXPECT_EQ(queries[1].at("level"), "study");
    EXPECT_EQ(queries[1].at("matches"), 1);
    EXPECT_EQ(queries[2].at("level"), "series");
    EXPECT_EQ(queries[2].at("peer"), "pacs");
    EXPECT_EQ(queries[2].at("study"), studyUid);
    EXPECT_EQ(queries[2].at("matches"), 2);
    EXPECT_EQ(queries[2].at("problem"), "");
    EXPECT_EQ(queries[3].at("level"), "series");
    EXPECT_EQ(queries[3].at("peer"), "dead");
    EXPECT_NE(queries[3].at("problem"), "");
    bool listed = false;
    for (const nlohmann::json& a : auditRecords(dir / "audit.jsonl", "action")) {
        if (a.value("action", "") == "list_pacs_series" && a.at("values").at("peer") == "pacs") {
            listed = true;
            EXPECT_EQ(a.at("values").at("study"), studyUid) << a.dump();
        }
    }
    EXPECT_TRUE(listed);
    fs::remove_all(dir);
}

// A PACS that takes the connection and never answers: the search ends with one line naming
// the peer within query_timeout_seconds (2 s here), and the kiosk goes on.
TEST(NetKioskPacs, ASilentPeerEndsTheSearchWithALineWithinTheTimeout) {
    const fs::path dir = tempDir("net-kiosk-pacs-silent");
    const SilentPeer silent;
    writeConfig(dir, silent.port(), 2);
    const auto start = std::chrono::steady_clock::now();
    ChildProcess kiosk = startKiosk(dir, R"(search patient_id ANYONE
wait until searches >= 1 timeout 30
expect found == 0
expect searching == 0
load builtin:sample
wait loaded timeout 60
)");
    ASSERT_TRUE(waitUntil([&] { return !kiosk.running(); }, std::chrono::seconds(60)))
        << kiosk.log();
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    const std::string log = kiosk.log();
    EXPECT_EQ(log.find("pacs.session:"), std::string::npos) << log; // no step failed
    EXPECT_NE(log.find("dicom: search on pacs failed: "), std::string::npos) << log;
    EXPECT_LT(seconds, 30.0) << log;
    const auto queries = auditRecords(dir / "audit.jsonl", "query");
    ASSERT_EQ(queries.size(), 1U);
    EXPECT_NE(queries[0].at("problem"), "");
    fs::remove_all(dir);
}

} // namespace
} // namespace steerseg::test
