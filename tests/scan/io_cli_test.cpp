// `steerseg info` end to end: a corrupt scan gives exit code 1 and one line on stderr; the
// built-in sample gives exit code 0 and JSON.
#include "support/cli_run.hpp"
#include "support/io_test_files.hpp"
#include "support/test_data.hpp"

#include <fstream>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>
#include <sstream>
#include <sys/wait.h>

namespace steerseg::test {
namespace {

test::CliRun runInfo(const std::string& scan) {
    return test::runSteerseg("info '" + scan + "'");
}

TEST(CliInfo, CorruptFileGivesExitOneAndOneLine) {
    const auto dir = test::tempDir("cli-corrupt");
    auto bytes = test::niftiFile(test::obliqueGeometry({8, 8, 8}), std::vector<std::byte>(100));
    test::writeFile(dir / "corrupt.nii", bytes);
    const test::CliRun r = runInfo((dir / "corrupt.nii").string());
    EXPECT_EQ(r.exitCode, 1);
    EXPECT_TRUE(r.out.empty()) << r.out;
    ASSERT_FALSE(r.err.empty());
    EXPECT_EQ(r.err.find('\n'), r.err.size() - 1) << "more than one line: " << r.err;
    EXPECT_NE(r.err.find("corrupt.nii"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("but the file holds only 100 bytes"), std::string::npos) << r.err;
}

TEST(CliInfo, BuiltinSampleGivesJson) {
    const auto dir = test::tempDir("cli-sample");
    const test::CliRun r = runInfo("builtin:sample");
    EXPECT_EQ(r.exitCode, 0) << r.err;
    const auto j = nlohmann::json::parse(r.out); // throws, failing the test, if not JSON
    EXPECT_EQ(j.at("format"), "builtin");
    EXPECT_EQ(j.at("dims").size(), 3U);
    EXPECT_EQ(j.at("world"), "LPS");
}

} // namespace
} // namespace steerseg::test
