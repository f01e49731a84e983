// The PACS's actions in the workflow (model::SearchPacs, ListPacsSeries, RetrievePacs,
// CancelRetrieve): taken in every state without touching the scan or the state, garbled
// arguments refused, and each one in the audit log with what it asked.
#include "support/test_data.hpp"
#include "support/workflow_rig.hpp"
#include "workflow/audit_log.hpp"

#include <filesystem>
#include <fstream>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>
#include <sstream>

namespace steerseg::test {
namespace {

using model::State;

TEST(WorkflowPacs, SearchAndRetrieveAreTakenInEveryStateAndLeaveItAsItIs) {
    for (const State s : {State::NoScan, State::Loading, State::Inspect, State::Seeding,
                          State::Evolving, State::Paused, State::Review, State::Done}) {
        Rig r;
        r.driveTo(s);
        const int seeds = r.status().seeds;
        model::SearchPacs search;
        search.keys.patientId = "PID-A";
        search.keys.studyDate = "last_7_days";
        EXPECT_TRUE(r.act(search).accepted) << model::stateName(s);
        EXPECT_TRUE(r.act(model::RetrievePacs{"", "1.2.3", ""}).accepted) << model::stateName(s);
        EXPECT_TRUE(r.act(model::CancelRetrieve{}).accepted) << model::stateName(s);
        EXPECT_TRUE(r.act(model::ListPacsSeries{"", "1.2.3"}).accepted) << model::stateName(s);
        EXPECT_EQ(r.state(), s);
        EXPECT_EQ(r.status().seeds, seeds);
    }
}

TEST(WorkflowPacs, GarbledArgumentsAreRefusedWithTheirReason) {
    Rig r;
    const auto bad = r.act(model::RetrievePacs{"", "1.2.x", ""});
    EXPECT_FALSE(bad.accepted);
    EXPECT_NE(bad.reason.find("not a DICOM UID"), std::string::npos) << bad.reason;
    EXPECT_FALSE(r.act(model::RetrievePacs{"", "1.2.3", "x"}).accepted);
    const auto series = r.act(model::ListPacsSeries{"pacs", "1.2.x"});
    EXPECT_FALSE(series.accepted);
    EXPECT_NE(series.reason.find("series: the study"), std::string::npos) << series.reason;
    model::SearchPacs search;
    search.keys.patientName = std::string(65, 'A');
    const auto longName = r.act(search);
    EXPECT_FALSE(longName.accepted);
    EXPECT_NE(longName.reason.find("patient_name"), std::string::npos) << longName.reason;
}

TEST(WorkflowPacs, TheAuditLogRecordsWhatWasAsked) {
    const std::filesystem::path dir = tempDir("workflow-pacs-audit");
    const std::filesystem::path path = dir / "audit.jsonl";
    {
        workflow::AuditLog audit(path);
        Rig r(testSettings(), &audit);
        model::SearchPacs search;
        search.peer = "pacs";
        search.keys.patientId = "PID-A";
        ASSERT_TRUE(r.act(search).accepted);
        ASSERT_TRUE(r.act(model::RetrievePacs{"pacs", "1.2.3", "1.2.3.4"}).accepted);
        ASSERT_TRUE(r.act(model::ListPacsSeries{"pacs", "1.2.3"}).accepted);
        audit.pacs("retrieve", {{"peer", "pacs"}, {"received", 3}});
    }
    std::ifstream in(path);
    std::vector<nlohmann::json> records;
    for (std::string line; std::getline(in, line);) {
        records.push_back(nlohmann::json::parse(line));
    }
    ASSERT_GE(records.size(), 3U);
    const auto find = [&](const std::string& action) {
        for (const auto& r : records) {
            if (r.value("action", "") == action) {
                return r;
            }
        }
        return nlohmann::json();
    };
    EXPECT_EQ(find("search_pacs").at("values"),
              (nlohmann::json{{"peer", "pacs"}, {"patient_id", "PID-A"}}));
    EXPECT_EQ(find("retrieve_pacs").at("values"),
              (nlohmann::json{{"peer", "pacs"}, {"study", "1.2.3"}, {"series", "1.2.3.4"}}));
    EXPECT_EQ(find("list_pacs_series").at("values"),
              (nlohmann::json{{"peer", "pacs"}, {"study", "1.2.3"}}));
    EXPECT_EQ(records.back().at("event"), "retrieve");
    EXPECT_EQ(records.back().at("received"), 3);
    std::filesystem::remove_all(dir);
}

} // namespace
} // namespace steerseg::test
