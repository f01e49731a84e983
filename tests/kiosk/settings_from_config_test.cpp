// The start-up numerics check into the workflow's settings (kiosk/settings_from_config, issue
// 47): a speed this GPU failed is off, the configured one falls back to the first that passed,
// and when every speed failed the threshold speed runs with the alarm's why.
#include "config/kiosk_config.hpp"
#include "kiosk/settings_from_config.hpp"

#include <gtest/gtest.h>

namespace steerseg::test {
namespace {

using model::SpeedKind;

session::NumericsReport report(bool threshold, bool edge, bool classify) {
    session::NumericsReport r;
    r.speeds = {{SpeedKind::Threshold, threshold, 0.0, "", threshold ? "" : "t failed"},
                {SpeedKind::Edge, edge, 0.0, "", edge ? "" : "e failed"},
                {SpeedKind::Classify, classify, 0.0, "", classify ? "" : "c failed"}};
    return r;
}

TEST(KioskSettings, ASpeedTheGpuFailedIsOffAndTheDefaultFallsBack) {
    config::KioskConfig cfg = config::defaultConfig();
    cfg.speed.kind = SpeedKind::Classify;
    const session::NumericsReport classifyWrong = report(true, true, false);
    const workflow::Settings s = kiosk::workflowSettings(cfg, &classifyWrong);
    EXPECT_EQ(s.defaultSpeed, SpeedKind::Threshold);
    ASSERT_EQ(s.speedsOff.size(), 1U);
    EXPECT_EQ(s.speedsOff[0].kind, SpeedKind::Classify);
    EXPECT_EQ(s.speedsOff[0].why, "c failed");
    EXPECT_TRUE(s.defaultSpeedFailed.empty());

    cfg.speed.kind = SpeedKind::Edge;
    EXPECT_EQ(kiosk::workflowSettings(cfg, &classifyWrong).defaultSpeed, SpeedKind::Edge);
    const session::NumericsReport right = report(true, true, true);
    EXPECT_TRUE(kiosk::workflowSettings(cfg, &right).speedsOff.empty());
    EXPECT_TRUE(kiosk::workflowSettings(cfg).speedsOff.empty()) << "no check: nothing off";
}

TEST(KioskSettings, WhenEverySpeedFailedTheThresholdRunsAndSaysSo) {
    config::KioskConfig cfg = config::defaultConfig();
    const session::NumericsReport wrong = report(false, false, false);
    const workflow::Settings s = kiosk::workflowSettings(cfg, &wrong);
    EXPECT_EQ(s.defaultSpeed, SpeedKind::Threshold);
    EXPECT_EQ(s.defaultSpeedFailed, "t failed");
    ASSERT_EQ(s.speedsOff.size(), 2U);
    EXPECT_EQ(s.speedsOff[0].kind, SpeedKind::Edge);
    EXPECT_EQ(s.speedsOff[1].kind, SpeedKind::Classify);
}

} // namespace
} // namespace steerseg::test
