// The persistent outbox against a real PACS that is down: the object waits on disk with its
// reason, survives a restart of the console (a new Outbox over the same folder), and is
// delivered once Orthanc is back, exactly once in Orthanc's instance list, every attempt in the
// audit log.
#include "files/file_error.hpp"
#include "files/io_faults.hpp"
#include "net/net_harness.hpp"
#include "net/outbox.hpp"
#include "support/cli_run.hpp"
#include "support/test_data.hpp"
#include "workflow/audit_log.hpp"

#include <fstream>
#include <gtest/gtest.h>

namespace steerseg::test {
namespace {

namespace fs = std::filesystem;
using namespace std::chrono_literals;

TEST(NetOutbox, WaitsForAStoppedPacsAndDeliversOnceAfterARestart) {
    STEERSEG_REQUIRE_DATA(series, "lung-ct-ibsi/dicom/image");
    STEERSEG_REQUIRE_PROGRAM(OrthancServer::kProgram, "orthanc");
    const fs::path dir = tempDir("net-outbox");
    const fs::path object = series / "DCM_IMG_00007.dcm";
    OrthancServer pacs(dir);
    const auto resolve = [&](const std::string& name) -> std::optional<net::DicomPeer> {
        if (name != "pacs") {
            return std::nullopt;
        }
        return net::DicomPeer{OrthancServer::kAet, "127.0.0.1", pacs.dicomPort()};
    };
    const net::OutboxBackoff backoff{200ms, 800ms};
    net::SendOptions options;
    options.timeoutSeconds = 5;
    pacs.stop();
    {
        workflow::AuditLog audit(dir / "audit.jsonl");
        // The console's clock stands still unless the test moves it: "not due yet" cannot
        // depend on how long a loaded machine takes between two passes.
        auto now = std::chrono::system_clock::now();
        net::Outbox outbox(dir / "outbox", backoff, &audit, [&] { return now; });
        outbox.enqueue(object, "pacs");
        EXPECT_EQ(outbox.deliverDue(resolve, options), 0);
        const auto waiting = outbox.pending();
        ASSERT_EQ(waiting.size(), 1u);
        EXPECT_EQ(waiting[0].attempts, 1);
        EXPECT_NE(waiting[0].lastProblem.find("connection refused"), std::string::npos)
            << waiting[0].lastProblem;
        // Not due again before its delay: a pass now sends nothing.
        EXPECT_EQ(outbox.deliverDue(resolve, options), 0);
        EXPECT_EQ(outbox.pending().at(0).attempts, 1);
        now += 250ms;
        EXPECT_EQ(outbox.deliverDue(resolve, options), 0);
        EXPECT_EQ(outbox.pending().at(0).attempts, 2);
        EXPECT_EQ(outbox.delayAfter(2), 400ms);
        EXPECT_EQ(outbox.delayAfter(9), 800ms);
    } // the console stops here, its outbox left on disk

    pacs.start();
    workflow::AuditLog audit(dir / "audit.jsonl");
    net::Outbox restarted(dir / "outbox", backoff, &audit);
    ASSERT_EQ(restarted.pending().size(), 1u);
    int delivered = 0;
    EXPECT_TRUE(
        waitUntil([&] { return (delivered += restarted.deliverDue(resolve, options)) > 0; }, 5s));
    EXPECT_EQ(delivered, 1);
    EXPECT_TRUE(restarted.pending().empty());
    EXPECT_TRUE(fs::is_empty(dir / "outbox"));
    EXPECT_EQ(restarted.deliverDue(resolve, options), 0);
    EXPECT_EQ(pacs.get("/instances").size(), 1u);

    const auto log = workflow::readAuditLog(dir / "audit.jsonl");
    std::vector<nlohmann::json> sends;
    for (const auto& r : log.records) {
        if (r.at("event") == "send") {
            sends.push_back(r);
        }
    }
    ASSERT_EQ(sends.size(), 3u);
    EXPECT_FALSE(sends[0].at("accepted").get<bool>());
    EXPECT_EQ(sends[1].at("attempt"), 2);
    EXPECT_TRUE(sends[2].at("accepted").get<bool>());
    EXPECT_EQ(sends[2].at("attempt"), 3);
    EXPECT_EQ(sends[2].at("peer"), "pacs");
    EXPECT_FALSE(sends[2].at("sop_instance_uid").get<std::string>().empty());
    fs::remove_all(dir);
}

// The command line's outbox: `steerseg send --outbox` killed with kill -9 while it waits for a
// stopped Orthanc; the next run delivers what it left, once.
TEST(NetOutbox, AKilledSenderLeavesItsQueueToTheNextRun) {
    STEERSEG_REQUIRE_DATA(series, "lung-ct-ibsi/dicom/image");
    STEERSEG_REQUIRE_PROGRAM(OrthancServer::kProgram, "orthanc");
    const fs::path dir = tempDir("net-outbox-kill");
    OrthancServer pacs(dir);
    pacs.stop();
    const fs::path config = dir / "node.toml";
    std::ofstream(config) << "[audit]\npath = \"" << (dir / "audit.jsonl").string()
                          << "\"\n[dicom]\noutbox = \"" << (dir / "outbox").string()
                          << "\"\nretry_first_seconds = 0.2\nretry_longest_seconds = 0.5\n"
                             "[[dicom.peers]]\nname = \"pacs\"\naet = \"ORTHANC\"\n"
                             "host = \"127.0.0.1\"\nsend = true\nport = "
                          << pacs.dicomPort() << "\n";
    const std::string object = (series / "DCM_IMG_00011.dcm").string();
    {
        ChildProcess sender({steersegBinary().string(), "send", "--config", config.string(),
                             "--outbox", "--to", "pacs", "--wait", "60", object},
                            dir / "sender.log");
        ASSERT_TRUE(
            waitUntil([&] { return sender.log().find("attempt 2:") != std::string::npos; }, 10s))
            << sender.log();
        EXPECT_NE(sender.log().find("connection refused"), std::string::npos) << sender.log();
        sender.killHard();
    }
    ASSERT_EQ(net::Outbox(dir / "outbox").pending().size(), 1u);
    pacs.start();
    const CliRun next = runSteerseg("send --config " + config.string() + " --outbox --wait 10");
    EXPECT_EQ(next.exitCode, 0) << next.out << next.err;
    EXPECT_NE(next.out.find("delivered "), std::string::npos) << next.out;
    EXPECT_EQ(pacs.get("/instances").size(), 1u);
    EXPECT_TRUE(net::Outbox(dir / "outbox").pending().empty());
    const auto log = workflow::readAuditLog(dir / "audit.jsonl");
    ASSERT_FALSE(log.records.empty());
    EXPECT_EQ(log.records.back().at("event"), "send");
    EXPECT_TRUE(log.records.back().at("accepted").get<bool>());
    fs::remove_all(dir);
}

TEST(NetOutbox, AnUnknownPeerAndADamagedRecordAreReportedNotThrown) {
    STEERSEG_REQUIRE_DATA(series, "lung-ct-ibsi/dicom/image");
    const fs::path dir = tempDir("net-outbox-bad");
    net::Outbox outbox(dir / "outbox", {10ms, 10ms});
    outbox.enqueue(series / "DCM_IMG_00000.dcm", "gone");
    EXPECT_EQ(outbox.deliverDue([](const std::string&) { return std::nullopt; }, {}), 0);
    EXPECT_EQ(outbox.pending().at(0).lastProblem, "no peer named 'gone' to send to");
    std::ofstream(dir / "outbox" / "123-0.json") << "{ torn";
    std::vector<std::string> problems;
    EXPECT_EQ(outbox.pending(&problems).size(), 1u);
    ASSERT_EQ(problems.size(), 1u);
    EXPECT_NE(problems[0].find("123-0.json: not an outbox record"), std::string::npos);
    EXPECT_THROW(outbox.enqueue(dir / "missing.dcm", "gone"), files::FileError);
    fs::remove_all(dir);
}

// The fault-injection suite's rule (docs/reliability.md) on the outbox's two files: a failure
// at any write call of an enqueue leaves no entry, no half of one and no temporary, and the
// same enqueue succeeds once the fault is gone.
TEST(NetOutbox, AFailedEnqueueLeavesNothingAndARetryWorks) {
    STEERSEG_REQUIRE_DATA(series, "lung-ct-ibsi/dicom/image");
    const fs::path dir = tempDir("net-outbox-faults");
    const fs::path object = series / "DCM_IMG_00000.dcm";
    net::Outbox outbox(dir / "outbox", {10ms, 10ms});
    for (const files::IoCall call :
         {files::IoCall::Open, files::IoCall::Write, files::IoCall::Sync, files::IoCall::Rename}) {
        std::size_t calls = 0;
        {
            const files::IoFault count(call, -1, 0);
            outbox.enqueue(object, "pacs");
            calls = count.calls(call);
        }
        fs::remove_all(dir / "outbox");
        fs::create_directories(dir / "outbox");
        ASSERT_GE(calls, 2u) << "the object and its record";
        for (std::size_t nth = 0; nth < calls; ++nth) {
            SCOPED_TRACE("call " + std::to_string(static_cast<int>(call)) + " #" +
                         std::to_string(nth));
            {
                const files::IoFault fault(call, static_cast<int>(nth), EIO);
                EXPECT_THROW(outbox.enqueue(object, "pacs"), files::WriteError);
            }
            EXPECT_TRUE(fs::is_empty(dir / "outbox")) << "no entry, half entry or temporary";
            outbox.enqueue(object, "pacs");
            EXPECT_EQ(outbox.pending().size(), 1u);
            fs::remove_all(dir / "outbox");
            fs::create_directories(dir / "outbox");
        }
    }
    fs::remove_all(dir);
}

} // namespace
} // namespace steerseg::test
