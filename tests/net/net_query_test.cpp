// Query/retrieve against a real PACS: Orthanc on loopback ports, holding synthetic series of two
// patients (different dates and modalities) that the product's own C-STORE put there. C-FIND at
// study and series level through net/query_scu and `steerseg query`; C-GET and C-MOVE through
// `steerseg retrieve`, every image checked in the store byte for byte against what was sent and
// listed as a received series; a cancel, a silent peer and the command line's refusals.
#include "net/net_harness.hpp"
#include "net/query_scu.hpp"
#include "net/received_series.hpp"
#include "net/retrieve_scu.hpp"
#include "net/store_scu.hpp"
#include "support/cli_run.hpp"
#include "support/test_data.hpp"

#include <algorithm>
#include <chrono>
#include <dcmtk/config/osconfig.h> // must come first among DCMTK's headers
#include <dcmtk/dcmdata/dcdeftag.h>
#include <dcmtk/dcmdata/dcfilefo.h>
#include <dcmtk/dcmdata/dcuid.h>
#include <fstream>
#include <gtest/gtest.h>
#include <map>
#include <netinet/in.h>
#include <random>
#include <sys/socket.h>
#include <unistd.h>

namespace steerseg::test {
namespace {

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

struct SeriesSpec {
    std::string patientName;
    std::string patientId;
    std::string studyDate;
    std::string modality;
    std::string accession;
    std::string studyUid;
    std::string seriesUid;
    int seriesNumber = 1;
    int images = 1;
};

// SOP instance UID -> the pixel data's bytes, as sent.
using Pixels = std::map<std::string, std::vector<Uint16>>;

std::string newUid() {
    char uid[100];
    return dcmGenerateUniqueIdentifier(uid, SITE_INSTANCE_UID_ROOT);
}

// `spec.images` files of 16 x 16 random 16-bit pixels in `folder`.
std::vector<fs::path> writeSeries(const fs::path& folder, const SeriesSpec& spec, Pixels& pixels,
                                  std::mt19937& random) {
    fs::create_directories(folder);
    std::vector<fs::path> files;
    const bool ct = spec.modality == "CT";
    for (int n = 0; n < spec.images; ++n) {
        DcmFileFormat file;
        DcmDataset& d = *file.getDataset();
        const std::string sop = newUid();
        d.putAndInsertString(DCM_SOPClassUID, ct ? UID_CTImageStorage : UID_MRImageStorage);
        d.putAndInsertString(DCM_SOPInstanceUID, sop.c_str());
        d.putAndInsertString(DCM_StudyInstanceUID, spec.studyUid.c_str());
        d.putAndInsertString(DCM_SeriesInstanceUID, spec.seriesUid.c_str());
        d.putAndInsertString(DCM_PatientName, spec.patientName.c_str());
        d.putAndInsertString(DCM_PatientID, spec.patientId.c_str());
        d.putAndInsertString(DCM_StudyDate, spec.studyDate.c_str());
        d.putAndInsertString(DCM_StudyTime, "101500");
        d.putAndInsertString(DCM_AccessionNumber, spec.accession.c_str());
        d.putAndInsertString(DCM_StudyDescription, ("Study " + spec.accession).c_str());
        d.putAndInsertString(DCM_SeriesDescription,
                             ("Series " + std::to_string(spec.seriesNumber)).c_str());
        d.putAndInsertString(DCM_Modality, spec.modality.c_str());
        d.putAndInsertString(DCM_SeriesNumber, std::to_string(spec.seriesNumber).c_str());
        d.putAndInsertString(DCM_InstanceNumber, std::to_string(n + 1).c_str());
        d.putAndInsertString(DCM_ImagePositionPatient, ("0\\0\\" + std::to_string(n * 2)).c_str());
        d.putAndInsertString(DCM_ImageOrientationPatient, "1\\0\\0\\0\\1\\0");
        d.putAndInsertString(DCM_PixelSpacing, "0.5\\0.5");
        d.putAndInsertString(DCM_PhotometricInterpretation, "MONOCHROME2");
        d.putAndInsertUint16(DCM_SamplesPerPixel, 1);
        d.putAndInsertUint16(DCM_Rows, 16);
        d.putAndInsertUint16(DCM_Columns, 16);
        d.putAndInsertUint16(DCM_BitsAllocated, 16);
        d.putAndInsertUint16(DCM_BitsStored, 16);
        d.putAndInsertUint16(DCM_HighBit, 15);
        d.putAndInsertUint16(DCM_PixelRepresentation, 0);
        std::vector<Uint16> values(16 * 16);
        std::uniform_int_distribution<int> value(0, 65535);
        for (auto& v : values) {
            v = static_cast<Uint16>(value(random));
        }
        d.putAndInsertUint16Array(DCM_PixelData, values.data(), values.size());
        const fs::path path = folder / (sop + ".dcm");
        EXPECT_TRUE(file.saveFile(path.c_str(), EXS_LittleEndianExplicit).good());
        files.push_back(path);
        pixels[sop] = values;
    }
    return files;
}

// The SOP instance UID and pixels of a stored file.
std::pair<std::string, std::vector<Uint16>> readImage(const fs::path& path) {
    DcmFileFormat file;
    if (file.loadFile(path.c_str()).bad()) {
        return {};
    }
    OFString sop;
    file.getDataset()->findAndGetOFString(DCM_SOPInstanceUID, sop);
    const Uint16* values = nullptr;
    unsigned long count = 0;
    file.getDataset()->findAndGetUint16Array(DCM_PixelData, values, &count);
    return {sop.c_str(), std::vector<Uint16>(values, values + (values ? count : 0))};
}

// Every .dcm below `folder` holds one of `sent`'s instances with its pixels unchanged; the
// number of them.
int expectSameImages(const fs::path& folder, const Pixels& sent) {
    int n = 0;
    for (const fs::path& file : filesBelow(folder)) {
        if (file.filename().string().rfind(".receiving-", 0) == 0) {
            continue; // the mark of a series left incomplete (a cancel's), no image
        }
        const auto [sop, values] = readImage(file);
        const auto it = sent.find(sop);
        EXPECT_NE(it, sent.end()) << file << " is no instance that was sent";
        if (it != sent.end()) {
            EXPECT_EQ(values, it->second) << file << ": the pixel data differs";
            EXPECT_EQ(file.filename().string(), sop + ".dcm");
        }
        ++n;
    }
    return n;
}

std::size_t countLines(const std::string& text) {
    return static_cast<std::size_t>(std::count(text.begin(), text.end(), '\n'));
}

// Orthanc with the synthetic studies, knowing the node (STEERSEG at 127.0.0.1:nodePort) as a
// modality that may query, get and move; and the node's config naming it thrice.
class NetQuery : public ::testing::Test {
  protected:
    void SetUp() override {
        STEERSEG_REQUIRE_PROGRAM(OrthancServer::kProgram, "orthanc");
        dir = tempDir("net-query");
        nodePort = freePort();
        pacs = std::make_unique<OrthancServer>(
            dir,
            nlohmann::json{{"DicomModalities",
                            {{"steerseg",
                              {{"AET", "STEERSEG"}, {"Host", "127.0.0.1"}, {"Port", nodePort}}}}}});
        peer = net::DicomPeer{OrthancServer::kAet, "127.0.0.1", pacs->dicomPort(), false};
        std::mt19937 random(48);
        studyA = newUid();
        studyB1 = newUid();
        studyB2 = newUid();
        seriesA1 = newUid();
        seriesA2 = newUid();
        const SeriesSpec specs[] = {
            {"DOE^JANE", "PID-A", "20240105", "CT", "ACC-A1", studyA, seriesA1, 1, 5},
            {"DOE^JANE", "PID-A", "20240105", "CT", "ACC-A1", studyA, seriesA2, 2, 3},
            {"ROE^RICHARD", "PID-B", "20240320", "MR", "ACC-B1", studyB1, newUid(), 1, 4},
            {"ROE^RICHARD", "PID-B", "20230611", "CT", "ACC-B2", studyB2, newUid(), 1, 2},
        };
        std::vector<fs::path> files;
        for (const SeriesSpec& spec : specs) {
            const auto written = writeSeries(dir / "sent" / spec.seriesUid, spec, sent, random);
            files.insert(files.end(), written.begin(), written.end());
        }
        const auto outcomes = net::sendFiles(peer, files, {});
        for (const auto& o : outcomes) {
            ASSERT_TRUE(o.accepted) << o.file << ": " << o.problem;
        }
        ASSERT_EQ(pacs->get("/instances").size(), 14U);
        config = dir / "node.toml";
        std::ofstream(config) << "[dicom]\naet = \"STEERSEG\"\nport = " << nodePort
                              << "\nstore = \"" << (dir / "store").string() << "\"\n"
                              << peerEntry("pacs", pacs->dicomPort(), "query = true\n")
                              << peerEntry("pacsmove", pacs->dicomPort(),
                                           "query = true\nretrieve = \"move\"\n")
                              << peerEntry("archive", pacs->dicomPort(), "send = true\n");
    }

    static std::string peerEntry(const std::string& name, int port, const std::string& extra) {
        return "[[dicom.peers]]\nname = \"" + name +
               "\"\naet = \"ORTHANC\"\nhost = \"127.0.0.1\"\nport = " + std::to_string(port) +
               "\n" + extra;
    }

    CliRun steerseg(const std::string& words) const {
        return runSteerseg(words + " --config " + config.string());
    }

    fs::path dir;
    fs::path config;
    int nodePort = 0;
    std::unique_ptr<OrthancServer> pacs;
    net::DicomPeer peer;
    std::string studyA, studyB1, studyB2, seriesA1, seriesA2;
    Pixels sent;
};

// A study search on one key.
net::StudyQuery keys(std::string net::StudyQuery::*key, std::string value) {
    net::StudyQuery query;
    query.*key = std::move(value);
    return query;
}

std::vector<std::string> studyUids(const net::QueryResult<net::StudyMatch>& result) {
    std::vector<std::string> uids;
    for (const auto& m : result.matches) {
        uids.push_back(m.studyUid);
    }
    std::sort(uids.begin(), uids.end());
    return uids;
}

std::vector<std::string> sorted(std::vector<std::string> uids) {
    std::sort(uids.begin(), uids.end());
    return uids;
}

TEST_F(NetQuery, FindsStudiesByPatientNameDateModalityAndAccession) {
    const net::ScuOptions options;
    const auto byId = net::findStudies(peer, keys(&net::StudyQuery::patientId, "PID-B"), options);
    ASSERT_EQ(byId.problem, "");
    EXPECT_EQ(studyUids(byId), sorted({studyB1, studyB2}));
    EXPECT_FALSE(byId.truncated);

    const auto byName =
        net::findStudies(peer, keys(&net::StudyQuery::patientName, "DOE*"), options);
    ASSERT_EQ(byName.problem, "");
    ASSERT_EQ(byName.matches.size(), 1U);
    const net::StudyMatch& a = byName.matches[0];
    EXPECT_EQ(a.studyUid, studyA);
    EXPECT_EQ(a.patientName, "DOE^JANE");
    EXPECT_EQ(a.patientId, "PID-A");
    EXPECT_EQ(a.studyDate, "20240105");
    EXPECT_EQ(a.studyTime, "101500");
    EXPECT_EQ(a.description, "Study ACC-A1");
    EXPECT_EQ(a.accession, "ACC-A1");
    EXPECT_EQ(a.modalities, "CT");
    EXPECT_EQ(a.seriesCount, 2);
    EXPECT_EQ(a.instanceCount, 8);

    const auto byRange =
        net::findStudies(peer, keys(&net::StudyQuery::studyDate, "20240101-20240331"), options);
    ASSERT_EQ(byRange.problem, "");
    EXPECT_EQ(studyUids(byRange), sorted({studyA, studyB1}));
    const auto byDay =
        net::findStudies(peer, keys(&net::StudyQuery::studyDate, "20230611"), options);
    EXPECT_EQ(studyUids(byDay), std::vector<std::string>{studyB2});

    const auto byModality = net::findStudies(peer, keys(&net::StudyQuery::modality, "MR"), options);
    ASSERT_EQ(byModality.problem, "");
    ASSERT_EQ(studyUids(byModality), std::vector<std::string>{studyB1});
    EXPECT_EQ(byModality.matches[0].instanceCount, 4);

    const auto byAccession =
        net::findStudies(peer, keys(&net::StudyQuery::accession, "ACC-B2"), options);
    EXPECT_EQ(studyUids(byAccession), std::vector<std::string>{studyB2});
    const auto none =
        net::findStudies(peer, keys(&net::StudyQuery::patientName, "NOBODY*"), options);
    EXPECT_EQ(none.problem, "");
    EXPECT_TRUE(none.matches.empty());

    // Past the cap the rest is cancelled (C-CANCEL) and the answer says it was cut.
    const auto capped = net::findStudies(peer, {}, options, 1);
    EXPECT_EQ(capped.problem, "");
    EXPECT_EQ(capped.matches.size(), 1U);
    EXPECT_TRUE(capped.truncated);
}

TEST_F(NetQuery, FindsTheSeriesOfAStudy) {
    const auto result = net::findSeries(peer, studyA, {});
    ASSERT_EQ(result.problem, "");
    ASSERT_EQ(result.matches.size(), 2U);
    std::map<std::string, net::SeriesMatch> byUid;
    for (const auto& m : result.matches) {
        byUid[m.seriesUid] = m;
    }
    ASSERT_EQ(byUid.count(seriesA1), 1U);
    ASSERT_EQ(byUid.count(seriesA2), 1U);
    EXPECT_EQ(byUid[seriesA1].modality, "CT");
    EXPECT_EQ(byUid[seriesA1].number, "1");
    EXPECT_EQ(byUid[seriesA1].description, "Series 1");
    EXPECT_EQ(byUid[seriesA1].instanceCount, 5);
    EXPECT_EQ(byUid[seriesA2].instanceCount, 3);
}

TEST_F(NetQuery, QueryCommandPrintsLinesOrJson) {
    const CliRun json = steerseg("query --to pacs --patient-name DOE* --json");
    ASSERT_EQ(json.exitCode, 0) << json.err;
    const auto list = nlohmann::json::parse(json.out);
    ASSERT_EQ(list.size(), 1U);
    EXPECT_EQ(list[0].at("study_uid"), studyA);
    EXPECT_EQ(list[0].at("modalities"), nlohmann::json::array({"CT"}));
    EXPECT_EQ(list[0].at("instances"), 8);
    EXPECT_NE(json.err.find("1 study from pacs"), std::string::npos) << json.err;

    const CliRun lines = steerseg("query --to pacs --study-date 20240101-20241231");
    ASSERT_EQ(lines.exitCode, 0) << lines.err;
    EXPECT_EQ(countLines(lines.out), 2U) << lines.out;
    EXPECT_NE(lines.out.find("20240320 101500 MR ROE^RICHARD (PID-B), accession ACC-B1, Study "
                             "ACC-B1: 1 series, 4 images"),
              std::string::npos)
        << lines.out;

    const CliRun series = steerseg("query --to pacs --study " + studyA);
    ASSERT_EQ(series.exitCode, 0) << series.err;
    EXPECT_EQ(countLines(series.out), 2U) << series.out;
    EXPECT_NE(series.out.find("CT #2 Series 2: 3 images, series " + seriesA2), std::string::npos)
        << series.out;
}

TEST_F(NetQuery, RetrievesASeriesByGetIntoTheStore) {
    const fs::path store = dir / "get-store";
    const CliRun run = steerseg("retrieve --to pacs --study " + studyA + " --series " + seriesA2 +
                                " --store " + store.string());
    ASSERT_EQ(run.exitCode, 0) << run.out << run.err;
    // Filed as the Storage SCP files a pushed series, every image as it was sent.
    const fs::path folder = store / studyA / seriesA2;
    EXPECT_EQ(expectSameImages(store, sent), 3);
    EXPECT_EQ(filesBelow(folder).size(), 3U);
    // Progress from the responses, to the whole.
    EXPECT_NE(run.err.find("received 1 of "), std::string::npos) << run.err;
    EXPECT_NE(run.err.find("received 3 of 3 images"), std::string::npos) << run.err;
    EXPECT_EQ(run.err.find("received 4"), std::string::npos) << run.err;
    const auto listed = net::listReceivedSeries(store, std::chrono::seconds(0));
    ASSERT_EQ(listed.size(), 1U);
    EXPECT_EQ(listed[0].folder, folder);
    EXPECT_EQ(listed[0].images, 3);
    EXPECT_FALSE(listed[0].incomplete); // every image came: the C-GET's mark is gone
    EXPECT_EQ(listed[0].modality, "CT");
    EXPECT_EQ(listed[0].patient, "DOE JANE");
    EXPECT_NE(run.out.find("stored " + folder.string() + ": CT 2024-01-05"), std::string::npos)
        << run.out;
}

TEST_F(NetQuery, RetrievesAStudyByMoveThroughTheNodesPort) {
    const CliRun run = steerseg("retrieve --to pacsmove --study " + studyA);
    ASSERT_EQ(run.exitCode, 0) << run.out << run.err;
    const fs::path store = dir / "store"; // [dicom] store
    EXPECT_EQ(expectSameImages(store, sent), 8);
    EXPECT_EQ(filesBelow(store / studyA / seriesA1).size(), 5U);
    EXPECT_EQ(filesBelow(store / studyA / seriesA2).size(), 3U);
    EXPECT_NE(run.err.find("received 8 of 8 images"), std::string::npos) << run.err;
    const auto listed = net::listReceivedSeries(store, std::chrono::seconds(0));
    ASSERT_EQ(listed.size(), 2U);
    EXPECT_EQ(listed[0].images + listed[1].images, 8);
    EXPECT_FALSE(listed[0].incomplete || listed[1].incomplete); // the node's associations' marks
    EXPECT_EQ(countLines(run.out), 2U) << run.out;

    // The node's port taken (a running node): said so, nothing asked of the PACS.
    const int taken = ::socket(AF_INET, SOCK_STREAM | SOCK_CLOEXEC, 0);
    sockaddr_in addr{};
    addr.sin_family = AF_INET;
    addr.sin_addr.s_addr = htonl(INADDR_ANY);
    addr.sin_port = htons(static_cast<std::uint16_t>(nodePort));
    ASSERT_EQ(::bind(taken, reinterpret_cast<const sockaddr*>(&addr), sizeof addr), 0);
    ASSERT_EQ(::listen(taken, 4), 0);
    const CliRun busy = steerseg("retrieve --to pacsmove --study " + studyB1);
    ::close(taken);
    EXPECT_EQ(busy.exitCode, 1) << busy.err;
    EXPECT_NE(busy.err.find("cannot receive the moved images: cannot listen on port " +
                            std::to_string(nodePort)),
              std::string::npos)
        << busy.err;
    EXPECT_FALSE(fs::exists(store / studyB1));
}

TEST_F(NetQuery, ACancelEndsTheRetrieveWithCCancel) {
    net::RetrieveOptions how;
    how.store = dir / "cancel-store";
    std::vector<net::RetrieveProgress> seen;
    const auto outcome = net::retrieve(
        peer, {studyA, ""}, how, {}, [&](const net::RetrieveProgress& p) { seen.push_back(p); },
        [&] { return !seen.empty() && seen.back().received >= 1; });
    EXPECT_TRUE(outcome.cancelled) << outcome.problem;
    EXPECT_NE(outcome.problem.find("cancelled after"), std::string::npos) << outcome.problem;
    EXPECT_GE(outcome.progress.received, 1);
    EXPECT_LT(outcome.progress.received, 8);
    // What did come is whole, and its series is listed as incomplete.
    EXPECT_EQ(expectSameImages(how.store, sent), outcome.progress.received);
    const auto listed = net::listReceivedSeries(how.store, std::chrono::seconds(0));
    ASSERT_FALSE(listed.empty());
    EXPECT_TRUE(std::any_of(listed.begin(), listed.end(),
                            [](const net::ReceivedSeries& s) { return s.incomplete; }));
}

TEST_F(NetQuery, ProgressOfAGetReachesTheWhole) {
    net::RetrieveOptions how;
    how.store = dir / "progress-store";
    std::vector<net::RetrieveProgress> seen;
    const auto outcome = net::retrieve(peer, {studyA, ""}, how, {},
                                       [&](const net::RetrieveProgress& p) { seen.push_back(p); });
    ASSERT_EQ(outcome.problem, "");
    ASSERT_FALSE(seen.empty());
    EXPECT_EQ(seen.back().received, 8);
    EXPECT_EQ(seen.back().expected, 8);
    for (std::size_t n = 1; n < seen.size(); ++n) {
        EXPECT_GE(seen[n].received, seen[n - 1].received);
    }
    EXPECT_EQ(expectSameImages(how.store, sent), 8);
}

// A wrong called AE title is rejected, a PACS that is down refuses the connection: each one line
// and status 1; no match at all is an answer.
TEST_F(NetQuery, APeerThatRefusesSaysSo) {
    net::DicomPeer wrong = peer;
    wrong.aet = "NOTORTHANC";
    const auto rejected = net::findStudies(wrong, {}, {});
    EXPECT_NE(rejected.problem.find("association rejected by NOTORTHANC@127.0.0.1"),
              std::string::npos)
        << rejected.problem;
    const CliRun noMatch = steerseg("query --to pacs --patient-id X --timeout 5");
    EXPECT_EQ(noMatch.exitCode, 0) << noMatch.err; // no match is an answer
    EXPECT_EQ(noMatch.out, "");
    pacs->stop();
    const CliRun down = steerseg("query --to pacs --patient-id PID-A");
    EXPECT_EQ(down.exitCode, 1);
    EXPECT_NE(down.err.find("connection refused by ORTHANC@127.0.0.1"), std::string::npos)
        << down.err;
}

TEST(NetQuerySilent, ASilentPeerEndsWithinTheTimeout) {
    const SilentPeer silent;
    const net::DicomPeer peer{"SILENT", "127.0.0.1", silent.port(), false};
    net::ScuOptions options;
    options.timeoutSeconds = 2;
    const auto start = Clock::now();
    const auto found = net::findStudies(peer, keys(&net::StudyQuery::patientId, "X"), options);
    const double seconds = std::chrono::duration<double>(Clock::now() - start).count();
    EXPECT_NE(found.problem.find("no association with SILENT@127.0.0.1:" +
                                 std::to_string(silent.port()) + ": no answer within 2 s"),
              std::string::npos)
        << found.problem;
    EXPECT_LT(seconds, 5.0) << found.problem;

    net::RetrieveOptions how;
    how.store = tempDir("net-query-silent") / "store";
    const auto begin = Clock::now();
    const auto got = net::retrieve(peer, {"1.2.3", ""}, how, options);
    EXPECT_LT(std::chrono::duration<double>(Clock::now() - begin).count(), 5.0);
    EXPECT_NE(got.problem.find("SILENT@127.0.0.1"), std::string::npos) << got.problem;

    const fs::path config = tempDir("net-query-silent-cli") / "node.toml";
    std::ofstream(config) << "[[dicom.peers]]\nname = \"silent\"\naet = \"SILENT\"\nhost = "
                             "\"127.0.0.1\"\nquery = true\nport = "
                          << silent.port() << "\n";
    const auto cliStart = Clock::now();
    const CliRun cli = runSteerseg("query --to silent --timeout 2 --config " + config.string());
    EXPECT_LT(std::chrono::duration<double>(Clock::now() - cliStart).count(), 5.0);
    EXPECT_EQ(cli.exitCode, 1);
    EXPECT_EQ(countLines(cli.err), 1U) << cli.err;
    EXPECT_NE(cli.err.find("SILENT@127.0.0.1:" + std::to_string(silent.port()) +
                           ": no answer within 2 s"),
              std::string::npos)
        << cli.err;
}

TEST(NetQueryRefusals, BadRequestsAreRefusedWithExitTwo) {
    const fs::path config = tempDir("net-query-refusals") / "node.toml";
    std::ofstream(config) << "[[dicom.peers]]\nname = \"pacs\"\naet = \"PACS\"\nhost = "
                             "\"127.0.0.1\"\nport = 1\nquery = true\n"
                             "[[dicom.peers]]\nname = \"archive\"\naet = \"ARCH\"\nhost = "
                             "\"127.0.0.1\"\nport = 1\nsend = true\n";
    const std::string c = " --config " + config.string();
    const struct {
        std::string words;
        std::string says;
    } cases[] = {
        {"query --to nowhere", "no [[dicom.peers]] named 'nowhere'"},
        {"query --to archive", "the peer 'archive' may not be queried: give it query = true"},
        {"retrieve --to archive --study 1.2.3", "may not be queried"},
        {"query --to pacs --study-date 2024-01-05", "--study-date: '2024-01-05' is not YYYYMMDD"},
        {"query --to pacs --study-date 20240230", "is not YYYYMMDD"},
        {"query --to pacs --study-date 20240301-20240201", "ends before it begins"},
        {"query --to pacs --modality ct", "modality: 1 to 16 of A-Z"},
        {"query --to pacs --study 1.2.3 --patient-id X", "--patient-id searches studies"},
        {"query --to pacs --study ../etc", "--study: '../etc' is not a UID"},
        {"query", "give --to PEER"},
        {"retrieve --to pacs", "give --study UID"},
        {"retrieve --to pacs --study 1.2.x", "study '1.2.x' is not a UID"},
        {"retrieve --to pacs --study 1.2.3 --series a/b", "series 'a/b' is not a UID"},
        {"retrieve --to pacs --study 1.2.3 --timeout 0", "--timeout: 1..600"},
    };
    for (const auto& k : cases) {
        const CliRun run = runSteerseg(k.words + c);
        EXPECT_EQ(run.exitCode, 2) << k.words << ": " << run.err;
        EXPECT_NE(run.err.find(k.says), std::string::npos) << k.words << ": " << run.err;
    }
}

} // namespace
} // namespace steerseg::test
