// `steerseg --self-test`'s GL-free checks: folders, config, controller nodes, the report.
#include "cli/self_test_checks.hpp"
#include "support/test_data.hpp"
#include "support/unprivileged.hpp"

#include <fstream>
#include <gtest/gtest.h>
#include <unistd.h>

namespace steerseg::test {
namespace {

using cli::CheckLevel;

bool isEmptyFolder(const std::filesystem::path& p) {
    return std::filesystem::is_directory(p) && std::filesystem::is_empty(p);
}

TEST(SelfTestFolders, CreatesAMissingFolderAndLeavesNoProbe) {
    const auto dir = tempDir("self-test-folders") / "a" / "b";
    const cli::CheckResult r = cli::checkWritableFolder("export folder", dir);
    EXPECT_EQ(r.level, CheckLevel::Ok) << r.detail;
    EXPECT_NE(r.detail.find(dir.string()), std::string::npos) << r.detail;
    EXPECT_TRUE(isEmptyFolder(dir));
}

TEST(SelfTestFolders, AFileInTheWayFails) {
    const auto dir = tempDir("self-test-file");
    std::ofstream(dir / "file") << "x";
    const cli::CheckResult r = cli::checkWritableFolder("export folder", dir / "file");
    EXPECT_EQ(r.level, CheckLevel::Fail);
    EXPECT_NE(r.detail.find("cannot create (Not a directory)"), std::string::npos) << r.detail;
    const cli::CheckResult below = cli::checkWritableFolder("export folder", dir / "file" / "x");
    EXPECT_EQ(below.level, CheckLevel::Fail);
    EXPECT_NE(below.detail.find("cannot create"), std::string::npos) << below.detail;
}

// Root writes through a mode of 0555, not into /proc.
TEST(SelfTestFolders, AFolderThatRefusesFilesFails) {
    std::filesystem::path folder = "/proc";
    if (::geteuid() != 0) {
        folder = tempDir("self-test-ro") / "ro";
        std::filesystem::create_directories(folder);
        std::filesystem::permissions(folder, std::filesystem::perms::owner_read |
                                                 std::filesystem::perms::owner_exec);
    }
    const cli::CheckResult r = cli::checkWritableFolder("autosave folder", folder);
    EXPECT_EQ(r.level, CheckLevel::Fail);
    EXPECT_NE(r.detail.find("cannot create a file"), std::string::npos) << r.detail;
}

// Issue 25, item 1: the audit file itself, opened for append as the service opens it; the folder's
// check passes in each of these cases.
TEST(SelfTestAuditLog, OpensTheFileForAppendAsTheServiceWould) {
    const auto dir = tempDir("self-test-audit");
    const cli::CheckResult fresh = cli::checkAuditLog(dir / "audit.jsonl");
    EXPECT_EQ(fresh.level, CheckLevel::Ok) << fresh.detail;
    // Not created: one made by a self-test as root would be root's, not the service's.
    EXPECT_FALSE(std::filesystem::exists(dir / "audit.jsonl"));
    // A folder of that name.
    std::filesystem::create_directories(dir / "folder.jsonl");
    const cli::CheckResult folder = cli::checkAuditLog(dir / "folder.jsonl");
    EXPECT_EQ(folder.level, CheckLevel::Fail);
    EXPECT_NE(folder.detail.find("a folder of that name is in the way"), std::string::npos)
        << folder.detail;
    EXPECT_EQ(cli::checkWritableFolder("audit log folder", dir).level, CheckLevel::Ok);
    // A file the service user may read but not write, in a folder it may write.
    std::filesystem::permissions(dir, std::filesystem::perms::all);
    std::ofstream(dir / "theirs.jsonl") << "{}\n";
    std::filesystem::permissions(dir / "theirs.jsonl", std::filesystem::perms::owner_read |
                                                           std::filesystem::perms::owner_write |
                                                           std::filesystem::perms::others_read);
    const std::string level = runUnprivileged([&] {
        const cli::CheckResult r = cli::checkAuditLog(dir / "theirs.jsonl");
        return std::string(r.level == CheckLevel::Fail ? "fail: " : "pass: ") + r.detail;
    });
    EXPECT_EQ(level.rfind("fail: ", 0), 0u) << level;
    EXPECT_NE(level.find("may not append to it (permission denied)"), std::string::npos) << level;
}

TEST(SelfTestConfig, ProblemsFailWithEachListed) {
    config::LoadedConfig loaded;
    loaded.applied = {"/etc/steerseg/steerseg.toml"};
    EXPECT_EQ(cli::checkConfig(loaded).level, CheckLevel::Ok);
    EXPECT_EQ(cli::checkConfig(loaded).detail, "built-in defaults < /etc/steerseg/steerseg.toml");

    const auto dir = tempDir("self-test-config");
    std::ofstream(dir / "bad.toml") << "[export]\nfolder = 3\n[nonsense]\n";
    const auto bad =
        config::loadConfig({{dir / "bad.toml", true}}, [](std::string_view) { return true; });
    const cli::CheckResult r = cli::checkConfig(bad);
    EXPECT_EQ(r.level, CheckLevel::Fail);
    ASSERT_EQ(r.problems.size(), bad.problems.size());
    EXPECT_GE(r.problems.size(), 2U);
    EXPECT_NE(r.problems[0].find("bad.toml"), std::string::npos) << r.problems[0];
}

TEST(SelfTestControllers, FindsTheNodeKindsAndIgnoresOthers) {
    const auto dev = tempDir("self-test-dev");
    std::filesystem::create_directories(dev / "input");
    for (const char* name : {"hidraw0", "hidraw3", "gpiochip0", "input/event2", "input/mouse0",
                             "input/js0", "tty0", "input/event10"}) {
        std::ofstream(dev / name) << "";
    }
    std::filesystem::permissions(dev / "hidraw3", std::filesystem::perms::none);
    const auto nodes = cli::findControllerNodes(dev);
    ASSERT_EQ(nodes.size(), 5U);
    EXPECT_EQ(nodes[0].node, dev / "gpiochip0");
    EXPECT_EQ(nodes[0].kind, "gpiochip");
    EXPECT_EQ(nodes[1].node, dev / "hidraw0");
    EXPECT_EQ(nodes[2].node, dev / "hidraw3");
    EXPECT_EQ(nodes[3].kind, "input event");
    // Root opens anything: only another user sees the node it may not open.
    EXPECT_EQ(nodes[2].accessible, ::geteuid() == 0);
    EXPECT_TRUE(nodes[1].accessible);

    const cli::CheckResult r = cli::checkControllers(nodes);
    EXPECT_EQ(r.level, CheckLevel::Ok);
    EXPECT_EQ(r.detail, std::string("1 gpiochip (1 open to this user), 2 hidraw (") +
                            (::geteuid() == 0 ? "2" : "1") +
                            " open to this user), 2 input event (2 open to this user)");
    EXPECT_EQ(r.problems.size(), ::geteuid() == 0 ? 0U : 1U);
}

TEST(SelfTestControllers, NoneIsAWarningNotAFailure) {
    const auto dev = tempDir("self-test-nodev");
    const cli::CheckResult r = cli::checkControllers(cli::findControllerNodes(dev));
    EXPECT_EQ(r.level, CheckLevel::Warn);
    EXPECT_EQ(cli::checkControllers(cli::findControllerNodes(dev / "missing")).level,
              CheckLevel::Warn);
}

TEST(SelfTestReport, OneLinePerCheckAndTheVerdict) {
    std::vector<cli::CheckResult> results{{"gl", CheckLevel::Ok, "OpenGL ES 3.2", {}},
                                          {"controllers", CheckLevel::Warn, "none", {}}};
    EXPECT_FALSE(cli::anyFailed(results));
    EXPECT_EQ(cli::formatReport(results), "steerseg self-test\n"
                                          "  ok    gl: OpenGL ES 3.2\n"
                                          "  warn  controllers: none\n"
                                          "self-test: passed with 1 warning(s)\n");
    results.push_back({"config", CheckLevel::Fail, "1 problem(s)", {"a.toml:1:1: x: bad"}});
    EXPECT_TRUE(cli::anyFailed(results));
    const std::string report = cli::formatReport(results);
    EXPECT_NE(report.find("  FAIL  config: 1 problem(s)\n          a.toml:1:1: x: bad\n"),
              std::string::npos)
        << report;
    EXPECT_NE(report.find("self-test: FAILED, 1 required check(s) failed\n"), std::string::npos);
    EXPECT_TRUE(cli::checkUser(true).has_value());
    EXPECT_FALSE(cli::checkUser(false).has_value());
}

} // namespace
} // namespace steerseg::test
