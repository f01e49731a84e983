// `steerseg kiosk` on hostile input: bad options, scripts that are not scripts, a garbled
// config, a scan that cannot be read, outputs that cannot be written. Each ends with one line
// and its exit status, or goes on (on the defaults, in the state the workflow promises) and
// finishes the session; none crashes or hangs. Offscreen at 320x200, so each takes seconds.
#include "support/cli_run.hpp"
#include "support/test_data.hpp"

#include <algorithm>
#include <array>
#include <cstring>
#include <fstream>
#include <gtest/gtest.h>
#include <unistd.h>
#include <utility>

namespace steerseg::test {
namespace {

// --max-seconds: a session that stops making progress fails instead of hanging the test.
const std::string kKiosk =
    "kiosk --allow-root --platform offscreen --size 320x200 --max-seconds 60 ";

std::string firstLine(const std::string& err) {
    return err.substr(0, err.find('\n'));
}

long lineCount(const std::string& text) {
    return std::count(text.begin(), text.end(), '\n');
}

void writeText(const std::filesystem::path& path, const std::string& text) {
    std::ofstream out(path, std::ios::binary);
    out << text;
}

// The kiosk's relative outputs (the default export folder and audit log) land in a fresh
// folder of the test's own: each test runs in its own process under CTest.
class KioskCli : public ::testing::Test {
  protected:
    void SetUp() override {
        const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
        dir = tempDir(std::string("kiosk-cli-") + info->name());
        std::filesystem::current_path(dir);
    }
    // Runs a session written here.
    CliRun session(const std::string& text, const std::string& more = "") {
        writeText(dir / "s.session", text);
        return runSteerseg(kKiosk + "--script " + (dir / "s.session").string() + " " + more);
    }
    std::filesystem::path dir;
};

// A folder no one can create files in: root writes through a mode of 0555, not into /proc.
std::filesystem::path readOnlyFolder(const std::filesystem::path& base) {
    if (::geteuid() == 0) {
        return "/proc";
    }
    const auto ro = base / "read-only";
    std::filesystem::create_directories(ro);
    std::filesystem::permissions(ro, std::filesystem::perms::owner_read |
                                         std::filesystem::perms::owner_exec);
    return ro;
}

TEST_F(KioskCli, BadOptionsAreTwo) {
    const CliRun size = runSteerseg("kiosk --allow-root --platform offscreen --size 10x10");
    EXPECT_EQ(size.exitCode, 2) << size.err;
    EXPECT_EQ(firstLine(size.err),
              "steerseg kiosk: --size: width and height must be 64..16384, got '10x10'");
    const CliRun platform = runSteerseg("kiosk --allow-root --platform bogus");
    EXPECT_EQ(platform.exitCode, 2) << platform.err;
    EXPECT_EQ(firstLine(platform.err),
              "steerseg kiosk: --platform: expected auto, kms, window or offscreen, got 'bogus'");
}

// No DRM device here: the failing step in one line, exit 3 (no display).
TEST_F(KioskCli, KmsWithoutADrmDeviceIsThree) {
    if (std::filesystem::exists("/dev/dri")) {
        GTEST_SKIP()
            << "/dev/dri exists: the KMS display may open here (platform_kms_display tests it)";
    }
    const CliRun r = runSteerseg("kiosk --allow-root --platform kms --size 320x200");
    EXPECT_EQ(r.exitCode, 3) << r.err;
    EXPECT_EQ(r.err, "steerseg kiosk: kms: no DRM device (/dev/dri/card*): /dev/dri: No such file "
                     "or directory\n");
}

TEST_F(KioskCli, ScriptsThatAreNotScriptsAreTwo) {
    std::string withNul = "load builtin:sample\n";
    withNul += std::string(1, '\0') + "\x7f" + "ELF";
    writeText(dir / "nul.session", withNul);
    std::string controls;
    for (int n = 0; n < 3000; ++n) {
        controls += static_cast<char>(1 + (n * 7) % 31);
    }
    writeText(dir / "controls.session", controls);
    writeText(dir / "huge.session", std::string(3 << 20, '#'));
    writeText(dir / "empty.session", "# nothing but a comment\n");
    const std::array<std::pair<std::string, std::string>, 6> cases = {{
        {"missing.session", "missing.session: no such script file"},
        {".", ": is a folder, not a script file"},
        {"nul.session", "nul.session: not a text file (a NUL byte at offset 20)"},
        {"controls.session", "controls.session: not a text file (control characters on"},
        {"huge.session", "huge.session: the script is larger than 1048576 bytes"},
        {"empty.session", "empty.session: the script has no steps"},
    }};
    for (const auto& [file, message] : cases) {
        const CliRun r = runSteerseg(kKiosk + "--script " + (dir / file).string());
        EXPECT_EQ(r.exitCode, 2) << file << ": " << r.err;
        EXPECT_NE(firstLine(r.err).find(message), std::string::npos) << file << ": " << r.err;
        EXPECT_EQ(lineCount(r.err), 1) << file << ": the line alone, got\n" << r.err;
    }
}

// Every problem named as file:line:column: key, nothing of the file applied (its export folder
// included), and the session runs to its end on the defaults.
TEST_F(KioskCli, GarbledConfigRunsOnTheDefaults) {
    writeText(dir / "bad.toml", "[export]\nfolder = \"elsewhere\"\n[frame]\nbudget_ms = \"fast\"\n"
                                "[display]\nrotation = 45\nsparkle = true\n");
    writeText(dir / "broken.toml", "[display\nplatform = = kms\n");
    const std::string script = "load builtin:sample\n"
                               "wait loaded timeout 30\n"
                               "seed 80 56 52 4\n"
                               "finish\n"
                               "wait state review timeout 10\n"
                               "export\n"
                               "wait state done timeout 30\n"
                               "expect exported contains steerseg-export/sample_\n";
    const CliRun bad = session(script, "--config " + (dir / "bad.toml").string());
    EXPECT_EQ(bad.exitCode, 0) << bad.err;
    const std::string file = "steerseg kiosk: config: " + (dir / "bad.toml").string();
    EXPECT_NE(bad.err.find(file + ":4:13: frame.budget_ms: "), std::string::npos) << bad.err;
    EXPECT_NE(bad.err.find(file + ":6:12: display.rotation: "), std::string::npos) << bad.err;
    EXPECT_NE(bad.err.find(file + ":7:1: display.sparkle: unknown key"), std::string::npos)
        << bad.err;
    EXPECT_FALSE(std::filesystem::exists(dir / "elsewhere"));

    const CliRun broken = session(script, "--config " + (dir / "broken.toml").string());
    EXPECT_EQ(broken.exitCode, 0) << broken.err;
    EXPECT_NE(broken.err.find("steerseg kiosk: config: " + (dir / "broken.toml").string() + ":1:"),
              std::string::npos)
        << broken.err;
}

// A NIfTI file whose header declares 16^3 uint8 voxels but that holds 100 bytes of them.
void writeTruncatedNifti(const std::filesystem::path& path) {
    std::array<char, 352> header{};
    const auto put = [&](std::size_t at, auto value) {
        std::memcpy(header.data() + at, &value, sizeof value);
    };
    put(0, std::int32_t{348});
    const std::array<std::int16_t, 8> dims = {3, 16, 16, 16, 1, 1, 1, 1};
    std::memcpy(header.data() + 40, dims.data(), sizeof dims);
    put(70, std::int16_t{2}); // NIFTI_TYPE_UINT8
    put(72, std::int16_t{8});
    for (std::size_t n = 0; n < 8; ++n) {
        put(76 + 4 * n, 1.0F);
    }
    put(108, 352.0F);
    std::memcpy(header.data() + 344, "n+1", 4);
    writeText(path, std::string(header.data(), header.size()) + std::string(100, '\x05'));
}

// The reader's message reaches the operator, the workflow stays without a scan, and the next
// load works.
TEST_F(KioskCli, TruncatedScanLeavesNoScan) {
    writeTruncatedNifti(dir / "cut.nii");
    const CliRun r = session("load " + (dir / "cut.nii").string() +
                             "\n"
                             "wait state no_scan timeout 20\n"
                             "expect message contains \"cut.nii: header says 16x16x16 uint8\"\n"
                             "expect message contains \"holds only 100 bytes\"\n"
                             "expect loaded\n");
    EXPECT_EQ(r.exitCode, 1) << r.err;
    EXPECT_NE(r.err.find("expect loaded"), std::string::npos) << r.err;
    EXPECT_EQ(r.err.find("expect message"), std::string::npos) << r.err;

    const CliRun again = session("load " + (dir / "cut.nii").string() +
                                 "\n"
                                 "wait state no_scan timeout 20\n"
                                 "load builtin:sample\n"
                                 "wait loaded timeout 30\n"
                                 "expect state inspect\n");
    EXPECT_EQ(again.exitCode, 0) << again.err;
}

// Issue 25, item 1: a lost audit log refuses export until acknowledged, and the session ends
// with status 4 and the records that never reached it counted, not 0.
TEST_F(KioskCli, ALostAuditLogRefusesExportUntilAcknowledgedAndExitsFour) {
    std::filesystem::create_directories(dir / "steerseg-export" / "audit.jsonl");
    const CliRun r = session("load builtin:sample\nwait loaded timeout 30\nseed 64 64 48 4\n"
                             "finish\nexport a.nii.gz\nexpect state review\n"
                             "expect message contains acknowledge\nacknowledge_audit\n"
                             "export a.nii.gz\nwait state done timeout 30\n");
    EXPECT_EQ(r.exitCode, 4) << r.err;
    EXPECT_TRUE(std::filesystem::exists(dir / "a.nii.gz")) << r.err;
    EXPECT_NE(r.err.find("a folder of that name is in the way"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("audit records could not be written"), std::string::npos) << r.err;
}

TEST_F(KioskCli, UnwritableOutputsAreFour) {
    writeText(dir / "file", "not a folder");
    const CliRun under = session("frame a.png\n", "--frames " + (dir / "file/frames").string());
    EXPECT_EQ(under.exitCode, 4) << under.err;
    EXPECT_EQ(under.err, "steerseg kiosk: " + (dir / "file/frames").string() +
                             ": cannot create the --frames folder (Not a directory)\n");
    const auto ro = readOnlyFolder(dir);
    const CliRun frames = session("frame a.png\n", "--frames " + (ro / "frames").string());
    EXPECT_EQ(frames.exitCode, 4) << frames.err;
    EXPECT_EQ(lineCount(frames.err), 1) << frames.err;
    EXPECT_NE(frames.err.find((ro / "frames").string() + ": cannot create the --frames folder"),
              std::string::npos)
        << frames.err;
    const CliRun stats = session("frame a.png\n", "--stats " + (ro / "stats.json").string());
    EXPECT_EQ(stats.exitCode, 4) << stats.err;
    EXPECT_EQ(lineCount(stats.err), 1) << stats.err;
    EXPECT_NE(stats.err.find((ro / "stats.json").string() + ": cannot write the --stats file"),
              std::string::npos)
        << stats.err;
}

// The export fails with the writer's message, the work stays in review, and an export that
// can be written still goes through.
TEST_F(KioskCli, ExportToAReadOnlyFolderStaysInReview) {
    const auto target = readOnlyFolder(dir) / "mask.nii.gz";
    const CliRun r = session("load builtin:sample\n"
                             "wait loaded timeout 30\n"
                             "seed 80 56 52 4\n"
                             "finish\n"
                             "wait state review timeout 10\n"
                             "export " +
                                 target.string() +
                                 "\n"
                                 "expect state review\n"
                                 "expect message contains \"" +
                                 target.string() + ": the folder " + target.parent_path().string() +
                                 "\"\n"
                                 "export mask.nii.gz\n"
                                 "wait state done timeout 30\n",
                             "--frames " + (dir / "out").string());
    EXPECT_EQ(r.exitCode, 0) << r.err;
    EXPECT_NE(r.err.find("steerseg kiosk: export refused: " + target.string() + ": the folder " +
                         target.parent_path().string()),
              std::string::npos)
        << r.err;
    EXPECT_TRUE(std::filesystem::exists(dir / "out/mask.nii.gz"));
}

// Issue 49: a new user's relative --frames. $OUT names the folder once, so `export
// $OUT/mask.nii.gz` lands in it (not in out/out/, refused as a missing folder, the session
// waiting in review), whether --frames was relative or had a trailing slash.
TEST_F(KioskCli, OutNamesARelativeFramesFolderOnce) {
    const std::array<std::pair<std::string, std::string>, 2> cases{
        {{"out", "out"}, {"out2/", "out2"}}}; // --frames, the folder it names
    for (const auto& [frames, folder] : cases) {
        const CliRun r = session("load builtin:sample\n"
                                 "wait loaded timeout 30\n"
                                 "seed 80 56 52 4\n"
                                 "finish\n"
                                 "wait state review timeout 10\n"
                                 "export $OUT/mask.nii.gz\n"
                                 "wait state done timeout 30\n"
                                 "frame $OUT/done.png\n",
                                 "--frames " + frames);
        EXPECT_EQ(r.exitCode, 0) << frames << ": " << r.err;
        const std::filesystem::path out = dir / folder;
        EXPECT_TRUE(std::filesystem::exists(out / "mask.nii.gz")) << frames << ": " << r.err;
        EXPECT_TRUE(std::filesystem::exists(out / "done.png")) << frames;
        EXPECT_FALSE(std::filesystem::exists(out / folder)) << frames;
    }
}

} // namespace
} // namespace steerseg::test
