#include "support/workflow_rig.hpp"

#include <filesystem>
#include <fstream>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

namespace steerseg::test {
namespace {

using namespace workflow;

using namespace model;
namespace fs = std::filesystem;

std::vector<nlohmann::json> readLines(const fs::path& path) {
    std::vector<nlohmann::json> out;
    std::ifstream in(path);
    std::string line;
    while (std::getline(in, line)) {
        out.push_back(nlohmann::json::parse(line)); // throws (fails the test) on a bad line
    }
    return out;
}

std::chrono::steady_clock::time_point steadyAt(double seconds) {
    return std::chrono::steady_clock::time_point(
        std::chrono::duration_cast<std::chrono::steady_clock::duration>(
            std::chrono::duration<double>(seconds)));
}

TEST(WorkflowAudit, EveryActionAndTransitionIsAJsonLine) {
    const fs::path dir = fs::path(testing::TempDir()) / "workflow-audit";
    fs::remove_all(dir);
    const fs::path path = dir / "logs" / "audit.jsonl";
    double now = 10.0;
    {
        AuditLog log(path, fixedTime, [&] { return steadyAt(now); });
        ASSERT_TRUE(log.ok());
        Rig rig(testSettings(), &log);
        rig.load();
        now = 12.5;
        ASSERT_TRUE(rig.act(Probe{{15.0, 6.0, 4.0}, 3.0}).accepted);
        ASSERT_FALSE(rig.act(ApplyPreset{"liver"}).accepted);
        rig.seed();
        ASSERT_TRUE(rig.act(NudgeParam{Param::Eps, 2.0}).accepted);
        EXPECT_TRUE(rig.status().message.empty());
    }
    const std::vector<nlohmann::json> lines = readLines(path);
    ASSERT_GE(lines.size(), 8U);
    for (const nlohmann::json& j : lines) {
        EXPECT_TRUE(j.contains("time") && j.contains("mono") && j.contains("state") &&
                    j.contains("event") && j.contains("scan"))
            << j.dump();
        EXPECT_EQ(j["time"], "2026-11-23T13:01:40.000Z");
    }
    // load_scan, then its transition to loading, then the load's own transition to inspect.
    EXPECT_EQ(lines[0]["event"], "action");
    EXPECT_EQ(lines[0]["action"], "load_scan");
    EXPECT_EQ(lines[0]["state"], "no_scan");
    EXPECT_EQ(lines[0]["values"]["path"], "fake.nii.gz");
    EXPECT_EQ(lines[0]["accepted"], true);
    EXPECT_EQ(lines[0]["mono"], 0.0);
    EXPECT_EQ(lines[1]["event"], "transition");
    EXPECT_EQ(lines[1]["from"], "no_scan");
    EXPECT_EQ(lines[1]["to"], "loading");
    EXPECT_EQ(lines[2]["to"], "inspect");
    EXPECT_EQ(lines[2]["cause"], "load");
    EXPECT_EQ(lines[2]["scan"], "fake:scan");

    const auto find = [&](const std::string& action) {
        for (const nlohmann::json& j : lines) {
            if (j.value("action", "") == action) {
                return j;
            }
        }
        return nlohmann::json();
    };
    const nlohmann::json probe = find("probe");
    EXPECT_EQ(probe["state"], "inspect");
    EXPECT_EQ(probe["values"]["voxel"], nlohmann::json::array({15.0, 6.0, 4.0}));
    EXPECT_EQ(probe["values"]["radius_mm"], 3.0);
    EXPECT_EQ(probe["result"]["T"], 1000.0);
    EXPECT_EQ(probe["result"]["eps"], 25.0); // stddev 10 * 2 < the floor
    EXPECT_EQ(probe["mono"], 2.5);
    const nlohmann::json preset = find("apply_preset");
    EXPECT_EQ(preset["accepted"], false);
    EXPECT_EQ(preset["reason"], "unknown preset 'liver'");
    const nlohmann::json seed = find("add_seed");
    EXPECT_EQ(seed["result"]["seeds"], 1);
    EXPECT_EQ(seed["scan"], "fake:scan");
    const nlohmann::json nudge = find("nudge_param");
    EXPECT_EQ(nudge["values"]["param"], "eps");
    EXPECT_EQ(nudge["result"]["eps"], 29.0);
    bool seeding = false;
    for (const nlohmann::json& j : lines) {
        seeding |= j["event"] == "transition" && j["from"] == "inspect" && j["to"] == "seeding" &&
                   j["cause"] == "add_seed";
    }
    EXPECT_TRUE(seeding);
}

TEST(WorkflowAudit, AnUnwritableLogIsReportedOnceAndNeverThrows) {
    AuditLog log("/dev/null/audit.jsonl");
    EXPECT_FALSE(log.ok());
    Rig rig(testSettings(), &log);
    EXPECT_NE(rig.status().auditProblem.find("/dev/null/audit.jsonl"), std::string::npos);
    rig.load();
    rig.seed();
    EXPECT_EQ(rig.state(), State::Seeding);
    ASSERT_TRUE(log.takeError().has_value()); // for the journal, once
    EXPECT_FALSE(log.takeError().has_value());
}

// Issue 25, item 1: the loss of the audit trail stays on screen through every notice until the
// log can be written again, and export waits for the operator's acknowledgement, which the log
// records (with everything held meanwhile) once it can be written.
TEST(WorkflowAudit, ALostLogStaysOnScreenAndExportWaitsForAcknowledgement) {
    const fs::path dir = fs::path(testing::TempDir()) / "workflow-audit-lost";
    fs::remove_all(dir);
    const fs::path path = dir / "audit.jsonl";
    fs::create_directories(path); // a folder where the file should be
    double now = 0.0;
    AuditLog log(path, fixedTime, [&] { return steadyAt(now); });
    ASSERT_FALSE(log.ok());
    Rig rig(testSettings(), &log);
    rig.driveTo(State::Paused);
    ASSERT_FALSE(rig.act(Resume{}).accepted); // a notice of its own
    EXPECT_FALSE(rig.status().message.empty());
    ASSERT_TRUE(rig.act(Finish{}).accepted);
    EXPECT_NE(rig.status().auditProblem.find("a folder of that name is in the way"),
              std::string::npos)
        << rig.status().auditProblem;
    EXPECT_FALSE(rig.status().allowed.contains(ActionKind::Export));
    EXPECT_TRUE(rig.status().allowed.contains(ActionKind::AcknowledgeAudit));
    const auto refused = rig.act(Export{"out.nii.gz"});
    ASSERT_FALSE(refused.accepted);
    EXPECT_NE(refused.reason.find("acknowledge"), std::string::npos) << refused.reason;
    EXPECT_EQ(rig.engine.exports.size(), 0U);
    EXPECT_FALSE(rig.status().auditProblem.empty());

    ASSERT_TRUE(rig.act(AcknowledgeAudit{}).accepted);
    EXPECT_TRUE(rig.status().auditAcknowledged);
    ASSERT_TRUE(rig.act(Export{"out.nii.gz"}).accepted);
    EXPECT_EQ(rig.state(), State::Done);
    EXPECT_FALSE(rig.status().auditProblem.empty()) << "replaced by the export's notice";

    // The folder goes: within a second of retries everything held is written, in order.
    fs::remove(path);
    rig.wf->update();
    EXPECT_FALSE(log.ok()) << "retried within the second";
    now = 2.0;
    rig.wf->update();
    ASSERT_TRUE(log.ok()) << log.problem();
    EXPECT_TRUE(rig.status().auditProblem.empty());
    EXPECT_FALSE(rig.status().auditAcknowledged);
    EXPECT_FALSE(rig.status().allowed.contains(ActionKind::AcknowledgeAudit));
    const std::vector<nlohmann::json> lines = readLines(path);
    ASSERT_GE(lines.size(), 10U);
    EXPECT_EQ(lines.front()["action"], "load_scan");
    bool acknowledged = false;
    bool exported = false;
    for (const nlohmann::json& j : lines) {
        acknowledged |= j.value("action", "") == "acknowledge_audit" && j["accepted"] == true;
        exported |= acknowledged && j.value("action", "") == "export" && j["accepted"] == true;
    }
    EXPECT_TRUE(acknowledged && exported);
    ASSERT_TRUE(log.takeError().has_value()); // the outage
    const auto back = log.takeError();        // and its end, for the journal
    ASSERT_TRUE(back.has_value());
    EXPECT_NE(back->find("written again"), std::string::npos) << *back;
}

TEST(WorkflowAudit, NothingToAcknowledgeWhileTheLogIsWritten) {
    const fs::path path = fs::path(testing::TempDir()) / "workflow-audit-kept.jsonl";
    AuditLog log(path);
    Rig rig(testSettings(), &log);
    rig.driveTo(State::Review);
    const auto refused = rig.act(AcknowledgeAudit{});
    EXPECT_FALSE(refused.accepted);
    EXPECT_NE(refused.reason.find("nothing to acknowledge"), std::string::npos);
    EXPECT_TRUE(rig.act(Export{"out.nii.gz"}).accepted);
}

TEST(WorkflowAudit, ActionValuesNameEveryArgument) {
    EXPECT_EQ(actionValues(SetParam{Param::Alpha, 0.5}),
              (nlohmann::json{{"param", "alpha"}, {"value", 0.5}}));
    EXPECT_EQ(actionValues(PageSlice{SliceAxis::Coronal, -2}),
              (nlohmann::json{{"axis", "coronal"}, {"delta", -2}}));
    EXPECT_EQ(actionValues(Undo{}), nlohmann::json::object());
    // Bad UTF-8 from a script is replaced, not thrown.
    AuditLog log(fs::path(testing::TempDir()) / "workflow-audit-utf8.jsonl");
    log.action(State::NoScan, LoadScan{"\xff\xfe"}, nullptr, "", false, "bad");
    EXPECT_TRUE(log.ok());
}

} // namespace
} // namespace steerseg::test
