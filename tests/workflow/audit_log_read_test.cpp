#include "workflow/audit_log.hpp"

#include <filesystem>
#include <fstream>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>

namespace steerseg::test {
namespace {

using namespace workflow;

using namespace model;
namespace fs = std::filesystem;

fs::path freshFile(const std::string& name) {
    const fs::path dir = fs::path(testing::TempDir()) / "audit-read";
    fs::create_directories(dir);
    const fs::path path = dir / name;
    fs::remove(path);
    return path;
}

void writeText(const fs::path& path, const std::string& text) {
    std::ofstream(path, std::ios::binary) << text;
}

std::string readText(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    std::stringstream text;
    text << in.rdbuf();
    return text.str();
}

TEST(AuditLogRead, WholeLogReadsEveryRecord) {
    const fs::path path = freshFile("whole.jsonl");
    {
        AuditLog log(path);
        log.transition(State::NoScan, State::Loading, "load_scan", "s", "");
        log.action(State::Loading, Quit{}, nullptr, "s", true, "");
    }
    const AuditLogContents read = readAuditLog(path);
    ASSERT_EQ(read.records.size(), 2U);
    EXPECT_EQ(read.records[0]["event"], "transition");
    EXPECT_EQ(read.records[1]["action"], "quit");
    EXPECT_FALSE(read.torn);
    EXPECT_TRUE(read.problems.empty());
}

TEST(AuditLogRead, TornLastLineIsReportedAndSkipped) {
    const fs::path path = freshFile("torn.jsonl");
    writeText(path,
              "{\"event\":\"action\",\"n\":1}\n{\"event\":\"action\",\"n\":2}\n{\"event\":\"tra");
    const AuditLogContents read = readAuditLog(path);
    ASSERT_EQ(read.records.size(), 2U);
    EXPECT_EQ(read.records[1]["n"], 2);
    ASSERT_TRUE(read.torn);
    EXPECT_NE(read.torn->find("line 3"), std::string::npos) << *read.torn;
    EXPECT_TRUE(read.problems.empty());
}

TEST(AuditLogRead, WholeRecordWithoutItsNewlineIsKept) {
    const fs::path path = freshFile("no-newline.jsonl");
    writeText(path, "{\"n\":1}\n{\"n\":2}");
    const AuditLogContents read = readAuditLog(path);
    ASSERT_EQ(read.records.size(), 2U);
    ASSERT_TRUE(read.torn);
    EXPECT_NE(read.torn->find("kept"), std::string::npos) << *read.torn;
}

TEST(AuditLogRead, DamagedLineInTheMiddleIsAProblemNotATear) {
    const fs::path path = freshFile("middle.jsonl");
    writeText(path, "{\"n\":1}\n{\"n\":\n{\"n\":3}\n");
    const AuditLogContents read = readAuditLog(path);
    ASSERT_EQ(read.records.size(), 2U);
    EXPECT_FALSE(read.torn);
    ASSERT_EQ(read.problems.size(), 1U);
    EXPECT_NE(read.problems[0].find("line 2"), std::string::npos) << read.problems[0];
}

TEST(AuditLogRead, MissingFileIsOneClearError) {
    const fs::path path = freshFile("missing.jsonl");
    try {
        (void)readAuditLog(path);
        FAIL() << "no error for a missing log";
    } catch (const std::runtime_error& e) {
        EXPECT_NE(std::string(e.what()).find("missing.jsonl"), std::string::npos) << e.what();
    }
}

// A log reopened after a crash goes on on a line of its own: the torn line stays torn (and is
// skipped), every record written since reads back.
TEST(AuditLogRead, ReopenedLogContinuesAfterATornLine) {
    const fs::path path = freshFile("continued.jsonl");
    writeText(path, "{\"n\":1}\n{\"event\":\"act");
    {
        AuditLog log(path);
        ASSERT_TRUE(log.ok());
        log.transition(State::NoScan, State::Loading, "load_scan", "s", "");
    }
    const std::string text = readText(path);
    EXPECT_NE(text.find("{\"event\":\"act\n{"), std::string::npos) << text;
    const AuditLogContents read = readAuditLog(path);
    ASSERT_EQ(read.records.size(), 2U);
    EXPECT_EQ(read.records[1]["to"], "loading");
    ASSERT_EQ(read.problems.size(), 1U); // the old torn line, now in the middle
    EXPECT_FALSE(read.torn);
}

} // namespace
} // namespace steerseg::test
