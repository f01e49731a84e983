// The appliance checks its GPU's numbers itself (issue 47): on a GPU that computes a speed
// wrong (a build of the app with the classify speed's gather broken through its test seam),
// `--self-test` names that speed and exits 1, and the kiosk starts with it off, a banner that
// says why, the check in the audit log and a SetSpeed to it refused; on a GPU that computes
// them right, every speed passes and the audit log says so.
#include "support/cli_run.hpp"
#include "support/test_data.hpp"

#include <cstdlib>
#include <fstream>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

namespace steerseg::test {
namespace {

const std::string kKiosk =
    "kiosk --allow-root --platform offscreen --size 320x200 --max-seconds 60 --script ";

// The session: the classify speed asked for after a load, and a seed grown a little.
constexpr const char* kSession = R"(load builtin:sample
wait loaded timeout 30
expect state inspect
speed classify
probe 80 56 52 6
seed 80 56 52 4
run
wait iterations 3 timeout 60
)";

class KioskGpuCheck : public ::testing::Test {
  protected:
    void SetUp() override {
        const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
        dir = tempDir(std::string("kiosk-gpu-check-") + info->name());
        std::filesystem::current_path(dir);
        std::ofstream(dir / "s.session") << kSession;
    }
    void TearDown() override { ::unsetenv("STEERSEG_BINARY"); }
    static void useBrokenBuild() {
        ::setenv("STEERSEG_BINARY", STEERSEG_BROKEN_CLASSIFY_BINARY, 1);
    }
    // The audit log's records of `event` ("action", "numerics_check", ...).
    std::vector<nlohmann::json> records(const std::string& event) const {
        std::vector<nlohmann::json> out;
        std::ifstream in(dir / "steerseg-export" / "audit.jsonl");
        for (std::string line; std::getline(in, line);) {
            const nlohmann::json r = nlohmann::json::parse(line);
            if (r.value("event", std::string()) == event) {
                out.push_back(r);
            }
        }
        return out;
    }
    static const nlohmann::json& speed(const nlohmann::json& check, const std::string& name) {
        for (const nlohmann::json& s : check.at("speeds")) {
            if (s.at("speed") == name) {
                return s;
            }
        }
        throw std::runtime_error("no " + name + " in the check");
    }
    std::filesystem::path dir;
};

TEST_F(KioskGpuCheck, SelfTestNamesTheSpeedThisGpuComputesWrong) {
    useBrokenBuild();
    const CliRun r = runSteerseg("--self-test --allow-root");
    EXPECT_EQ(r.exitCode, 1) << r.out << r.err;
    EXPECT_NE(r.out.find("FAIL  numerics classify: WRONG on this GPU"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("gathered features within"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("ok    numerics threshold: matches the CPU"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("ok    numerics edge: matches the CPU"), std::string::npos) << r.out;
}

TEST_F(KioskGpuCheck, TheKioskTurnsThatSpeedOffWithABannerAndAnAuditRecord) {
    useBrokenBuild();
    const CliRun r = runSteerseg(kKiosk + (dir / "s.session").string());
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_NE(r.err.find("GPU CHECK FAILED. The classify speed is off: this GPU computed it "
                         "wrong at start-up (gathered features within"),
              std::string::npos)
        << r.err;
    EXPECT_NE(r.err.find("The threshold speed runs instead."), std::string::npos) << r.err;
    const std::vector<nlohmann::json> checks = records("numerics_check");
    ASSERT_EQ(checks.size(), 1U);
    EXPECT_FALSE(checks[0].at("passed").get<bool>());
    EXPECT_FALSE(speed(checks[0], "classify").at("passed").get<bool>());
    EXPECT_TRUE(speed(checks[0], "threshold").at("passed").get<bool>());
    EXPECT_TRUE(speed(checks[0], "edge").at("passed").get<bool>());
    bool refused = false;
    for (const nlohmann::json& a : records("action")) {
        if (a.value("action", std::string()) == "set_speed") {
            refused = !a.at("accepted").get<bool>() &&
                      a.at("reason").get<std::string>().find("classify speed is off") !=
                          std::string::npos;
        }
    }
    EXPECT_TRUE(refused) << "SetSpeed classify was not refused";
}

TEST_F(KioskGpuCheck, OnAGpuThatComputesThemRightEverySpeedPasses) {
    const CliRun r = runSteerseg(kKiosk + (dir / "s.session").string());
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_EQ(r.err.find("GPU CHECK FAILED"), std::string::npos) << r.err;
    const std::vector<nlohmann::json> checks = records("numerics_check");
    ASSERT_EQ(checks.size(), 1U);
    EXPECT_TRUE(checks[0].at("passed").get<bool>()) << checks[0].dump();
    EXPECT_EQ(checks[0].at("speeds").size(), 3U);
}

} // namespace
} // namespace steerseg::test
