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

// Issue 25, item 4: a log reopened after a crash moves the torn fragment to <log>.torn and cuts
// the log back to its last whole line, so it stays valid JSON lines.
TEST(AuditLogRead, ReopenedLogMovesATornLineAside) {
    const fs::path path = freshFile("continued.jsonl");
    fs::path aside = path;
    aside += ".torn";
    fs::remove(aside);
    writeText(path, "{\"n\":1}\n{\"event\":\"act");
    {
        AuditLog log(path);
        ASSERT_TRUE(log.ok());
        const auto note = log.takeRepairNote();
        ASSERT_TRUE(note.has_value());
        EXPECT_NE(note->find(aside.string()), std::string::npos) << *note;
        log.transition(State::NoScan, State::Loading, "load_scan", "s", "");
    }
    const AuditLogContents read = readAuditLog(path);
    ASSERT_EQ(read.records.size(), 2U);
    EXPECT_EQ(read.records[1]["to"], "loading");
    EXPECT_TRUE(read.problems.empty());
    EXPECT_FALSE(read.torn);
    EXPECT_EQ(readText(aside), "{\"event\":\"act\n");
}

TEST(AuditLogRead, AWholeLastRecordOnlyGetsItsNewline) {
    const fs::path path = freshFile("whole-repaired.jsonl");
    writeText(path, "{\"n\":1}\n{\"n\":2}");
    EXPECT_TRUE(repairTornTail(path).has_value());
    EXPECT_EQ(readText(path), "{\"n\":1}\n{\"n\":2}\n");
    EXPECT_FALSE(repairTornTail(path).has_value());
}

} // namespace
} // namespace steerseg::test
