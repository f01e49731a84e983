// The DICOM node inside the kiosk, end to end (docs/dicom-network.md): DCMTK's storescu pushes
// the IBSI lung CT into the kiosk's Storage SCP as the scanner would; the kiosk (offscreen,
// scripted) lists it, loads it from the list, seeds, runs, exports, and its outbox sends the
// DICOM SEG to Orthanc, where the REST API shows it filed with the source's study.
#include "net/net_harness.hpp"
#include "net/received_series.hpp"
#include "support/test_data.hpp"

#include <algorithm>
#include <csignal>
#include <fstream>
#include <gtest/gtest.h>
#include <map>
#include <set>
#include <sstream>
#include <sys/socket.h>
#include <thread>
#include <unistd.h>

namespace steerseg::test {
namespace {

namespace fs = std::filesystem;

// Lists, loads, segments a little and exports; waits until the outbox is empty.
constexpr const char* kSession = R"(wait until received >= 1 timeout 60
load $RECEIVED
wait loaded timeout 60
expect state inspect
probe 102 100 30 5
seed 102 100 30 6
run
wait iterations 20 timeout 30
pause
wait state paused
finish
wait state review
export
wait state done timeout 30
expect volume_ml > 0
expect exported contains steerseg-export
wait until outbox == 0 timeout 30
)";

void writeConfig(const fs::path& dir, int port, int pacsPort, bool enabled = true) {
    // A failed send is retried after 0.3 s (doubling), so the PACS's return is seen soon.
    std::ofstream(dir / "kiosk.toml")
        << "[export]\nfolder = \"" << (dir / "steerseg-export").string()
        << "\"\nformats = [\"dcm\"]\n[audit]\npath = \"" << (dir / "audit.jsonl").string()
        << "\"\n[autosave]\nfolder = \"" << (dir / "autosave").string()
        << "\"\n[dicom]\nenabled = " << (enabled ? "true" : "false") << "\nport = " << port
        << "\nstore = \"" << (dir / "store").string() << "\"\noutbox = \""
        << (dir / "outbox").string()
        << "\"\nmin_free_mb = 0\nretry_first_seconds = 0.3\n"
           "[[dicom.peers]]\nname = \"scanner\"\naet = \"SCANNER\"\nhost = \"127.0.0.1\"\n"
           "receive = true\n"
           "[[dicom.peers]]\nname = \"pacs\"\naet = \"ORTHANC\"\nhost = \"127.0.0.1\"\n"
           "send = true\nport = "
        << pacsPort << "\n";
}

std::size_t countOf(const std::string& text, const std::string& what) {
    std::size_t n = 0;
    for (auto at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) {
        ++n;
    }
    return n;
}

// The scenario; with `pacsDown` Orthanc is stopped until the kiosk's first send has failed.
void runScenario(const fs::path& series, const std::string& name, bool pacsDown) {
    const fs::path dir = tempDir(name);
    OrthancServer pacs(dir);
    if (pacsDown) {
        pacs.stop();
    }
    const int port = freePort();
    writeConfig(dir, port, pacs.dicomPort());
    std::ofstream(dir / "node.session") << kSession;

    ChildProcess kiosk({steersegBinary().string(), "kiosk", "--allow-root", "--platform",
                        "offscreen", "--size", "480x320", "--max-seconds", "90", "--config",
                        (dir / "kiosk.toml").string(), "--script", (dir / "node.session").string(),
                        "--frames", (dir / "frames").string()},
                       dir / "kiosk.log");
    ASSERT_TRUE(waitUntil([&] { return kiosk.log().find("listening as") != std::string::npos; },
                          std::chrono::seconds(20)))
        << kiosk.log();
    const Finished pushed = runProgram({"storescu", "-aet", "SCANNER", "-aec", "STEERSEG", "+sd",
                                        "127.0.0.1", std::to_string(port), series.string()},
                                       dir);
    ASSERT_EQ(pushed.status, 0) << pushed.output;
    if (pacsDown) {
        // The SEG waits in the outbox (the panel says why) until the PACS is back.
        ASSERT_TRUE(
            waitUntil([&] { return kiosk.log().find("connection refused") != std::string::npos; },
                      std::chrono::seconds(60)))
            << kiosk.log();
        pacs.start();
    }

    ASSERT_TRUE(waitUntil([&] { return !kiosk.running(); }, std::chrono::seconds(100)))
        << kiosk.log();
    const std::string log = kiosk.log();
    EXPECT_NE(log.find("dicom: received "), std::string::npos) << log;
    EXPECT_NE(log.find("dicom: delivered "), std::string::npos) << log;
    EXPECT_EQ(log.find("refused object"), std::string::npos) << log; // the SCP took every image
    EXPECT_EQ(log.find("node.session:"), std::string::npos) << log;  // no step failed

    // Orthanc holds the SEG and its measurement report (docs/exports.md), in the source's study
    // (storescu sent the source to the kiosk only).
    const nlohmann::json instances = pacs.get("/instances?expand");
    ASSERT_EQ(instances.size(), 2U) << instances.dump();
    std::string sourceStudy;
    for (const auto& study : fs::directory_iterator(dir / "store")) {
        sourceStudy = study.path().filename().string();
    }
    std::set<std::string> modalities;
    for (const auto& instance : instances) {
        const nlohmann::json tags =
            pacs.get("/instances/" + instance.at("ID").get<std::string>() + "/simplified-tags");
        modalities.insert(tags.at("Modality").get<std::string>());
        EXPECT_EQ(tags.at("StudyInstanceUID"), sourceStudy);
        if (tags.at("Modality") == "SEG") {
            EXPECT_FALSE(tags.at("PerFrameFunctionalGroupsSequence").empty());
        }
    }
    EXPECT_EQ(modalities, (std::set<std::string>{"SEG", "SR"}));

    // The audit log has each attempt of each object: the failed ones while the PACS was down,
    // then the one it accepted, once.
    const std::string audit = readText(dir / "audit.jsonl");
    const std::size_t sends = countOf(audit, "\"event\":\"send\"");
    EXPECT_EQ(countOf(audit, "\"accepted\":true,\"attempt\""), 2U) << audit;
    if (pacsDown) {
        EXPECT_GE(sends, 4U) << audit;
    } else {
        EXPECT_EQ(sends, 2U) << audit;
    }
    EXPECT_TRUE(fs::is_empty(dir / "outbox"));
    fs::remove_all(dir);
}

TEST(NetKioskNode, ReceivedSeriesIsLoadedSegmentedAndItsSegSentToThePacs) {
    STEERSEG_REQUIRE_DATA(series, "lung-ct-ibsi/dicom/image");
    STEERSEG_REQUIRE_PROGRAM(OrthancServer::kProgram, "orthanc");
    STEERSEG_REQUIRE_PROGRAM("/usr/bin/storescu", "dcmtk");
    runScenario(series, "net-kiosk-node", false);
}

// Orthanc stopped when the kiosk exports: the SEG waits in the outbox and is delivered, once,
// when Orthanc is back, while the kiosk runs on.
TEST(NetKioskNode, ASegWaitsForThePacsAndIsDeliveredOnceItIsBack) {
    STEERSEG_REQUIRE_DATA(series, "lung-ct-ibsi/dicom/image");
    STEERSEG_REQUIRE_PROGRAM(OrthancServer::kProgram, "orthanc");
    STEERSEG_REQUIRE_PROGRAM("/usr/bin/storescu", "dcmtk");
    runScenario(series, "net-kiosk-node-pacs-down", true);
}

// kill -9 while the SEG waits for the PACS, right after the outbox counted a failed attempt:
// the outbox keeps it, the next start delivers it once, and the audit log has every attempt
// the outbox counted, none missing.
TEST(NetKioskNode, ASegPendingWhenTheKioskIsKilledIsDeliveredOnceAfterTheRestart) {
    STEERSEG_REQUIRE_DATA(series, "lung-ct-ibsi/dicom/image");
    STEERSEG_REQUIRE_PROGRAM(OrthancServer::kProgram, "orthanc");
    const fs::path dir = tempDir("net-kiosk-node-kill");
    OrthancServer pacs(dir);
    pacs.stop();
    writeConfig(dir, freePort(), pacs.dicomPort());
    // The series from its folder (receiving is the scenarios' part); the last wait holds the
    // kiosk with the SEG in the outbox until the kill.
    std::string session = kSession;
    session.replace(0, session.find("wait loaded"), "load " + series.string() + "\n");
    std::ofstream(dir / "export.session") << session;
    std::ofstream(dir / "drain.session") << "wait until outbox == 0 timeout 30\n";
    const auto kioskArgs = [&](const std::string& script) {
        return std::vector<std::string>{steersegBinary().string(),
                                        "kiosk",
                                        "--allow-root",
                                        "--platform",
                                        "offscreen",
                                        "--size",
                                        "160x120",
                                        "--max-seconds",
                                        "60",
                                        "--no-resume",
                                        "--config",
                                        (dir / "kiosk.toml").string(),
                                        "--script",
                                        (dir / script).string()};
    };
    // The moment the outbox has counted a failed attempt of every object (the SEG and its
    // report) on disk: each attempt's audit record is written by then (it comes first).
    const auto attempted = [&] {
        std::error_code ec;
        int records = 0;
        for (const auto& f : fs::directory_iterator(dir / "outbox", ec)) {
            if (f.path().extension() != ".json") {
                continue;
            }
            ++records;
            if (readText(f.path()).find("\"attempts\": 0") != std::string::npos) {
                return false;
            }
        }
        return records == 2;
    };
    {
        ChildProcess kiosk(kioskArgs("export.session"), dir / "kiosk.log");
        const auto end = std::chrono::steady_clock::now() + std::chrono::seconds(60);
        while (!attempted() && std::chrono::steady_clock::now() < end) {
            std::this_thread::sleep_for(std::chrono::milliseconds(1));
        }
        kiosk.killHard();
        ASSERT_TRUE(attempted()) << kiosk.log();
        kiosk.stop();
    }
    pacs.start();
    ChildProcess kiosk(kioskArgs("drain.session"), dir / "kiosk.log");
    ASSERT_TRUE(waitUntil([&] { return !kiosk.running(); }, std::chrono::seconds(60)))
        << kiosk.log();
    EXPECT_EQ(kiosk.log().find("drain.session:"), std::string::npos) << kiosk.log();

    const nlohmann::json instances = pacs.get("/instances?expand");
    ASSERT_EQ(instances.size(), 2U) << instances.dump() << kiosk.log(); // the SEG and its report
    std::set<std::string> modalities;
    for (const auto& instance : instances) {
        modalities.insert(
            pacs.get("/instances/" + instance.at("ID").get<std::string>() + "/simplified-tags")
                .at("Modality")
                .get<std::string>());
    }
    EXPECT_EQ(modalities, (std::set<std::string>{"SEG", "SR"}));
    EXPECT_TRUE(fs::is_empty(dir / "outbox"));
    // Per object, attempts 1, 2, ... N without a gap, only the last one accepted.
    std::map<std::string, std::vector<nlohmann::json>> byFile;
    for (const nlohmann::json& send : auditRecords(dir / "audit.jsonl", "send")) {
        byFile[send.at("file").get<std::string>()].push_back(send);
    }
    ASSERT_EQ(byFile.size(), 2U) << kiosk.log() << readText(dir / "audit.jsonl");
    for (const auto& [file, sends] : byFile) {
        for (std::size_t n = 0; n < sends.size(); ++n) {
            EXPECT_EQ(sends[n].at("attempt"), n + 1) << file << readText(dir / "audit.jsonl");
            EXPECT_EQ(sends[n].at("accepted").get<bool>(), n + 1 == sends.size())
                << file << readText(dir / "audit.jsonl");
        }
    }
    fs::remove_all(dir);
}

// The kiosk's node under load while the kiosk evolves (issue 48): 20 connections that say
// nothing and 5 that send half an association request and stop are open when storescu pushes
// the lung CT into the kiosk's port; it is served (storescu's own timeouts at 10 s) and stored
// whole, the series listed whole. The bound is generous for a loaded 2-core machine; the time
// taken is printed, and the kiosk's frame p90 meanwhile is tools/bench-dicom-kiosk.sh's figure.
TEST(NetKioskNode, ASeriesIsServedPastIdleConnectionsWhileTheKioskEvolves) {
    STEERSEG_REQUIRE_DATA(series, "lung-ct-ibsi/dicom/image");
    STEERSEG_REQUIRE_PROGRAM("/usr/bin/storescu", "dcmtk");
    STEERSEG_REQUIRE_PROGRAM("/usr/bin/echoscu", "dcmtk");
    const fs::path dir = tempDir("net-kiosk-node-load");
    const int port = freePort();
    writeConfig(dir, port, freePort());
    // The built-in sample evolving until the series is in, then the end.
    std::ofstream(dir / "load.session")
        << "load builtin:sample\nwait loaded timeout 60\nseed 64 84 48 3\nrun\n"
           "wait state evolving timeout 30\nwait until received >= 1 timeout 120\nquit\n";
    ChildProcess kiosk({steersegBinary().string(), "kiosk", "--allow-root", "--platform",
                        "offscreen", "--size", "480x320", "--no-resume", "--max-seconds", "150",
                        "--config", (dir / "kiosk.toml").string(), "--script",
                        (dir / "load.session").string()},
                       dir / "kiosk.log");
    ASSERT_TRUE(waitUntil([&] { return kiosk.log().find("listening as") != std::string::npos; },
                          std::chrono::seconds(20)))
        << kiosk.log();
    std::this_thread::sleep_for(std::chrono::seconds(5)); // the sample loaded and evolving

    const std::string rq = associateRequest("SCANNER", "STEERSEG");
    std::vector<int> idle;
    for (int n = 0; n < 25; ++n) {
        const int fd = connectLoopback(port);
        ASSERT_GE(fd, 0);
        if (n >= 20) {
            ::send(fd, rq.data(), rq.size() / 2, MSG_NOSIGNAL);
        }
        idle.push_back(fd);
    }
    // The first answer (an echo's association), then the series.
    const auto asked = std::chrono::steady_clock::now();
    const Finished echo = runProgram({"echoscu", "-aet", "SCANNER", "-aec", "STEERSEG", "-to", "10",
                                      "-ta", "10", "127.0.0.1", std::to_string(port)},
                                     dir);
    const double answered =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - asked).count();
    EXPECT_EQ(echo.status, 0) << echo.output << kiosk.log();
    EXPECT_LT(answered, 10.0) << kiosk.log();
    const auto start = std::chrono::steady_clock::now();
    const Finished pushed =
        runProgram({"storescu", "-aet", "SCANNER", "-aec", "STEERSEG", "-to", "10", "-ta", "10",
                    "-td", "10", "+sd", "127.0.0.1", std::to_string(port), series.string()},
                   dir);
    const double took =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    EXPECT_EQ(pushed.status, 0) << pushed.output << kiosk.log();
    EXPECT_LT(took, 20.0) << kiosk.log();
    std::printf("past 20 silent and 5 half-spoken connections, kiosk evolving: echo answered "
                "in %.2f s, storescu of 60 images (5 MB) in %.2f s\n",
                answered, took);
    for (const int fd : idle) {
        ::close(fd);
    }
    const auto listed = net::listReceivedSeries(dir / "store", std::chrono::seconds(0));
    ASSERT_EQ(listed.size(), 1U) << kiosk.log();
    EXPECT_EQ(listed.front().images, 60);
    EXPECT_FALSE(listed.front().incomplete);

    ASSERT_TRUE(waitUntil([&] { return !kiosk.running(); }, std::chrono::seconds(120)))
        << kiosk.log();
    const std::string log = kiosk.log();
    EXPECT_NE(log.find("dicom: received "), std::string::npos) << log;
    EXPECT_EQ(log.find("refused object"), std::string::npos) << log;
    EXPECT_EQ(log.find("load.session:"), std::string::npos) << log; // no step failed
    fs::remove_all(dir);
}

// A series whose sender aborted half way (storescu --abort) is listed incomplete by the kiosk
// and not offered: a script waiting for a received series goes on waiting through the settle
// time, until a complete send of the series comes (issue 48).
TEST(NetKioskNode, AnIncompleteSeriesIsNotOfferedUntilACompleteSend) {
    STEERSEG_REQUIRE_DATA(series, "lung-ct-ibsi/dicom/image");
    STEERSEG_REQUIRE_PROGRAM("/usr/bin/storescu", "dcmtk");
    const fs::path dir = tempDir("net-kiosk-node-incomplete");
    const int port = freePort();
    writeConfig(dir, port, freePort());
    std::ofstream(dir / "wait.session") << "wait until received >= 1 timeout 120\nquit\n";
    ChildProcess kiosk({steersegBinary().string(), "kiosk", "--allow-root", "--platform",
                        "offscreen", "--size", "160x120", "--no-resume", "--max-seconds", "150",
                        "--config", (dir / "kiosk.toml").string(), "--script",
                        (dir / "wait.session").string()},
                       dir / "kiosk.log");
    ASSERT_TRUE(waitUntil([&] { return kiosk.log().find("listening as") != std::string::npos; },
                          std::chrono::seconds(20)))
        << kiosk.log();
    std::vector<std::string> half{"storescu", "--abort",  "-aet",      "SCANNER",
                                  "-aec",     "STEERSEG", "127.0.0.1", std::to_string(port)};
    std::vector<fs::path> files;
    for (const auto& e : fs::directory_iterator(series)) {
        files.push_back(e.path());
    }
    std::sort(files.begin(), files.end());
    for (std::size_t n = 0; n < files.size() / 2; ++n) {
        half.push_back(files[n].string());
    }
    EXPECT_EQ(runProgram(half, dir).status, 0);
    EXPECT_TRUE(
        waitUntil([&] { return kiosk.log().find("dicom: incomplete ") != std::string::npos; },
                  std::chrono::seconds(15)))
        << kiosk.log();
    // Past the 3 s settle time the script still waits: the series is not offered.
    std::this_thread::sleep_for(std::chrono::seconds(5));
    EXPECT_TRUE(kiosk.running()) << kiosk.log();
    EXPECT_EQ(kiosk.log().find("dicom: received "), std::string::npos) << kiosk.log();

    const Finished whole = runProgram({"storescu", "-aet", "SCANNER", "-aec", "STEERSEG", "+sd",
                                       "127.0.0.1", std::to_string(port), series.string()},
                                      dir);
    EXPECT_EQ(whole.status, 0) << whole.output;
    EXPECT_TRUE(waitUntil([&] { return !kiosk.running(); }, std::chrono::seconds(60)))
        << kiosk.log();
    const std::string log = kiosk.log();
    EXPECT_NE(log.find("dicom: received "), std::string::npos) << log;
    EXPECT_EQ(log.find("wait.session:"), std::string::npos) << log; // the wait held
    fs::remove_all(dir);
}

// SIGTERM to the kiosk with an association half way (storescu frozen by SIGSTOP after a few
// images): the kiosk exits within 2 s with status 0, its node says which series it left
// incomplete, and the store lists it so.
TEST(NetKioskNode, AStopWithAnAssociationHalfWayLeavesItsSeriesIncomplete) {
    STEERSEG_REQUIRE_DATA(series, "lung-ct-ibsi/dicom/image");
    STEERSEG_REQUIRE_PROGRAM("/usr/bin/storescu", "dcmtk");
    const fs::path dir = tempDir("net-kiosk-node-stop");
    const int port = freePort();
    writeConfig(dir, port, freePort());
    ChildProcess kiosk({steersegBinary().string(), "kiosk", "--allow-root", "--platform",
                        "offscreen", "--size", "160x120", "--no-resume", "--max-seconds", "120",
                        "--config", (dir / "kiosk.toml").string()},
                       dir / "kiosk.log");
    ASSERT_TRUE(waitUntil([&] { return kiosk.log().find("listening as") != std::string::npos; },
                          std::chrono::seconds(20)))
        << kiosk.log();
    std::vector<std::string> argv{"storescu", "-aet",      "SCANNER",           "-aec",
                                  "STEERSEG", "127.0.0.1", std::to_string(port)};
    std::vector<std::string> files;
    for (const auto& e : fs::directory_iterator(series)) {
        files.push_back(e.path().string());
    }
    for (int round = 0; round < 20; ++round) { // 1200 C-STOREs: it is never done by itself
        argv.insert(argv.end(), files.begin(), files.end());
    }
    ChildProcess sender(argv, dir / "sender.log");
    const auto images = [&] {
        std::size_t n = 0;
        for (const fs::path& f : filesBelow(dir / "store")) {
            n += f.extension() == ".dcm" ? 1 : 0;
        }
        return n;
    };
    EXPECT_TRUE(waitUntil([&] { return images() >= 3; }, std::chrono::seconds(20))) << kiosk.log();
    sender.signal(SIGSTOP);
    const auto start = std::chrono::steady_clock::now();
    EXPECT_EQ(kiosk.stop(), 0) << kiosk.log();
    const double took =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    EXPECT_LT(took, 2.0) << kiosk.log();
    std::printf("SIGTERM to the kiosk with an association half way: exited in %.2f s\n", took);
    sender.killHard();
    sender.stop();
    EXPECT_NE(kiosk.log().find("dicom: incomplete series "), std::string::npos) << kiosk.log();
    const auto listed = net::listReceivedSeries(dir / "store", std::chrono::seconds(0));
    ASSERT_EQ(listed.size(), 1U);
    EXPECT_TRUE(listed.front().incomplete);
    fs::remove_all(dir);
}

// The node answers while the kiosk runs and goes with it on SIGTERM (exit 0); with the node off
// (the default) the same config opens no port.
TEST(NetKioskNode, OffOpensNoPortOnAnswersAndStopsWithTheKiosk) {
    STEERSEG_REQUIRE_PROGRAM("/usr/bin/echoscu", "dcmtk");
    const fs::path dir = tempDir("net-kiosk-node-onoff");
    for (const bool enabled : {false, true}) {
        const int port = freePort();
        writeConfig(dir, port, freePort(), enabled);
        ChildProcess kiosk({steersegBinary().string(), "kiosk", "--allow-root", "--platform",
                            "offscreen", "--size", "160x120", "--max-seconds", "60", "--config",
                            (dir / "kiosk.toml").string()},
                           dir / "kiosk.log");
        const std::string started = enabled ? "dicom: listening as" : "steerseg kiosk: offscreen";
        ASSERT_TRUE(waitUntil([&] { return kiosk.log().find(started) != std::string::npos; },
                              std::chrono::seconds(20)))
            << kiosk.log();
        const Finished echo = runProgram(
            {"echoscu", "-aet", "SCANNER", "-aec", "STEERSEG", "127.0.0.1", std::to_string(port)},
            dir);
        EXPECT_EQ(echo.status == 0, enabled) << echo.output;
        EXPECT_EQ(kiosk.stop(), 0) << kiosk.log();
        EXPECT_EQ(kiosk.log().find("dicom:") != std::string::npos, enabled) << kiosk.log();
    }
    fs::remove_all(dir);
}

} // namespace
} // namespace steerseg::test
