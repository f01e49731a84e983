// `steerseg input-monitor --replay`: a recording decoded through the real decoders and the
// shipped bindings, printed as control events and the actions they are bound to; and its
// mistakes (a missing file, options that do not go together) as one line each.
#include "support/cli_run.hpp"
#include "support/test_data.hpp"

#include <fstream>
#include <gtest/gtest.h>

namespace steerseg::test {
namespace {

const std::string kData = STEERSEG_INPUT_DATA_DIR;

bool has(const std::string& text, const std::string& part) {
    return text.find(part) != std::string::npos;
}

TEST(InputMonitorCli, ReplayPrintsEventsAndBoundActions) {
    const CliRun run = runSteerseg("input-monitor --replay " + kData + "/hub_unplug_mid_turn.rec");
    ASSERT_EQ(run.exitCode, 0) << run.err;
    EXPECT_TRUE(has(run.out, "replaying 8 records")) << run.out;
    EXPECT_TRUE(has(run.out, "0.100000 pedal press -> run\n")) << run.out;
    EXPECT_TRUE(has(run.out, "0.200000 shuttle_ring position 0.571429 -> nudge_selected 10\n"))
        << run.out;
    EXPECT_TRUE(has(run.out, "(repeat) -> nudge_selected 10\n")) << run.out;
    EXPECT_TRUE(has(run.out, "input: shuttle: disconnected\n")) << run.out;
    EXPECT_TRUE(has(run.out, "1.000000 pedal release -> pause\n")) << run.out;
    EXPECT_TRUE(has(run.out, "2.100000 shuttle_jog step +2 -> nudge_selected 2\n")) << run.out;
}

TEST(InputMonitorCli, ReplayOfABadRecordingSaysWhichLines) {
    const CliRun run = runSteerseg("input-monitor --replay " + kData + "/hub_garbage.rec");
    ASSERT_EQ(run.exitCode, 0) << run.err;
    EXPECT_TRUE(has(run.out, "input: shuttle: report of 1 bytes, expected 5")) << run.out;
    EXPECT_TRUE(has(run.out, "shuttle_jog step +1 -> nudge_selected 1")) << run.out;

    const std::string path = testing::TempDir() + "/not-a-recording.rec";
    std::ofstream(path) << "hello\n";
    const CliRun bad = runSteerseg("input-monitor --replay " + path);
    EXPECT_EQ(bad.exitCode, 1);
    EXPECT_TRUE(has(bad.out, path + ":1:")) << bad.out;
    EXPECT_TRUE(has(bad.err, "no records to replay")) << bad.err;
}

TEST(InputMonitorCli, Mistakes) {
    const CliRun missing = runSteerseg("input-monitor --replay /no/such.rec");
    EXPECT_EQ(missing.exitCode, 1) << missing.err;
    EXPECT_TRUE(has(missing.out, "/no/such.rec")) << missing.out;
    const CliRun both = runSteerseg("input-monitor --replay x.rec --seconds 2");
    EXPECT_EQ(both.exitCode, 2);
    EXPECT_TRUE(has(both.err, "--replay takes neither")) << both.err;
    const CliRun zero = runSteerseg("input-monitor --seconds 0");
    EXPECT_EQ(zero.exitCode, 2);
}

// Live, with whatever this machine has (usually nothing): it lists, watches and ends on time.
TEST(InputMonitorCli, LiveEndsAfterSecondsAndRecords) {
    const std::string rec = testing::TempDir() + "/monitor.rec";
    const CliRun run = runSteerseg("input-monitor --seconds 0.3 --record " + rec);
    ASSERT_EQ(run.exitCode, 0) << run.err;
    EXPECT_TRUE(has(run.out, "attached devices: ")) << run.out;
    EXPECT_TRUE(has(run.out, "watching 6 configured devices")) << run.out;
    std::ifstream in(rec);
    std::string first;
    std::getline(in, first);
    EXPECT_EQ(first, "# steerseg input recording 1");
}

} // namespace
} // namespace steerseg::test
