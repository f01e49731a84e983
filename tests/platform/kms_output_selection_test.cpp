// Connector and mode choice on connector lists recorded from real machines, and the one-line
// refusals when the configuration asks for something the hardware does not have.
#include "platform/kms/output_selection.hpp"

#include <gtest/gtest.h>
#include <string>

namespace steerseg::test {
namespace {

using platform::DisplayError;
using platform::DisplayOptions;
using platform::kms::ConnectorInfo;
using platform::kms::ModeInfo;
using platform::kms::parseModeRequest;
using platform::kms::selectOutput;

ModeInfo mode(int w, int h, int hz, bool preferred = false) {
    return ModeInfo{w, h, hz, preferred, std::to_string(w) + "x" + std::to_string(h)};
}

// A laptop: the panel (eDP-1, 1920x1200 preferred) and an empty HDMI port.
std::vector<ConnectorInfo> laptop() {
    return {
        {77, "eDP-1", true, 302, 189, {mode(1920, 1200, 60, true), mode(1920, 1200, 48)}},
        {86, "HDMI-A-1", false, 0, 0, {}},
    };
}

// A desk with two monitors: DP-1 is listed first but is off; HDMI-A-1 and DP-2 are on.
std::vector<ConnectorInfo> twoMonitors() {
    return {
        {90, "DP-1", false, 0, 0, {}},
        {95,
         "HDMI-A-1",
         true,
         527,
         296,
         {mode(1920, 1080, 60, true), mode(1920, 1080, 50), mode(1280, 720, 60)}},
        {99, "DP-2", true, 597, 336, {mode(2560, 1440, 144), mode(2560, 1440, 60, true)}},
    };
}

// A 4K console panel; its mode list has 1080p at three rates.
std::vector<ConnectorInfo> panel4k() {
    return {{41,
             "HDMI-A-1",
             true,
             698,
             393,
             {mode(3840, 2160, 60, true), mode(3840, 2160, 30), mode(1920, 1080, 50),
              mode(1920, 1080, 60), mode(1920, 1080, 30), mode(1280, 720, 60)}}};
}

std::string refusal(const std::vector<ConnectorInfo>& connectors, const DisplayOptions& options) {
    try {
        (void)selectOutput(connectors, options);
    } catch (const DisplayError& e) {
        return e.what();
    }
    return "(no error)";
}

TEST(KmsOutputSelection, LaptopUsesThePanelsPreferredMode) {
    const auto c = laptop();
    const auto choice = selectOutput(c, DisplayOptions{});
    EXPECT_EQ(c[choice.connector].name, "eDP-1");
    EXPECT_EQ(c[choice.connector].modes[choice.mode].width, 1920);
    EXPECT_EQ(c[choice.connector].modes[choice.mode].refreshHz, 60);
}

TEST(KmsOutputSelection, FirstConnectedConnectorWinsOverADisconnectedOneListedFirst) {
    const auto c = twoMonitors();
    const auto choice = selectOutput(c, DisplayOptions{});
    EXPECT_EQ(c[choice.connector].name, "HDMI-A-1");
    EXPECT_EQ(choice.mode, 0U);
}

TEST(KmsOutputSelection, NamedConnectorAndItsPreferredMode) {
    const auto c = twoMonitors();
    DisplayOptions options;
    options.connector = "DP-2";
    const auto choice = selectOutput(c, options);
    EXPECT_EQ(c[choice.connector].name, "DP-2");
    EXPECT_EQ(c[choice.connector].modes[choice.mode].refreshHz, 60); // preferred, not 144
}

TEST(KmsOutputSelection, ConfiguredModeOnA4kPanel) {
    const auto c = panel4k();
    DisplayOptions options;
    options.mode = "1920x1080";
    auto choice = selectOutput(c, options);
    EXPECT_EQ(c[0].modes[choice.mode].width, 1920);
    EXPECT_EQ(c[0].modes[choice.mode].refreshHz, 60); // the highest rate of that size
    options.mode = "1920x1080@50";
    choice = selectOutput(c, options);
    EXPECT_EQ(choice.mode, 2U);
    options.mode = "3840x2160@30";
    choice = selectOutput(c, options);
    EXPECT_EQ(choice.mode, 1U);
}

TEST(KmsOutputSelection, WithoutAPreferredModeTheLargestIsUsed) {
    const std::vector<ConnectorInfo> c{
        {5, "VGA-1", true, 0, 0, {mode(1024, 768, 60), mode(1280, 1024, 60), mode(800, 600, 60)}}};
    const auto choice = selectOutput(c, DisplayOptions{});
    EXPECT_EQ(choice.mode, 1U);
}

TEST(KmsOutputSelection, RefusalsNameWhatIsThere) {
    DisplayOptions options;
    options.connector = "HDMI-A-2";
    EXPECT_EQ(refusal(twoMonitors(), options),
              "kms: no connector named HDMI-A-2 (found: DP-1 (disconnected), HDMI-A-1, DP-2)");
    options.connector = "DP-1";
    EXPECT_EQ(refusal(twoMonitors(), options), "kms: connector DP-1 is not connected");
    options.connector = "";
    options.mode = "1920x1080@75";
    EXPECT_EQ(refusal(twoMonitors(), options),
              "kms: no mode 1920x1080@75 on HDMI-A-1 (modes: 1920x1080@60, 1920x1080@50, "
              "1280x720@60)");
    options.mode = "";
    std::vector<ConnectorInfo> none = laptop();
    none[0].connected = false;
    EXPECT_EQ(refusal(none, options),
              "kms: no connected connector (found: eDP-1 (disconnected), HDMI-A-1 (disconnected))");
    EXPECT_EQ(refusal({}, options), "kms: no connected connector (found: none)");
    const std::vector<ConnectorInfo> noModes{{3, "DSI-1", true, 0, 0, {}}};
    EXPECT_EQ(refusal(noModes, options), "kms: connector DSI-1 lists no modes");
}

TEST(KmsOutputSelection, ParsesModeStrings) {
    auto r = parseModeRequest("1920x1080");
    EXPECT_EQ(r.width, 1920);
    EXPECT_EQ(r.height, 1080);
    EXPECT_EQ(r.refreshHz, 0);
    r = parseModeRequest("1280x800@60");
    EXPECT_EQ(r.width, 1280);
    EXPECT_EQ(r.height, 800);
    EXPECT_EQ(r.refreshHz, 60);
}

TEST(KmsOutputSelection, RefusesBadModeStrings) {
    for (const std::string bad :
         {"", "1920", "1920x", "x1080", "1920x1080@", "1920x1080@0", "0x1080", "-1920x1080",
          "1920X1080", "1920x1080@60Hz", "1920 x 1080", "99999999999x1080", "axb"}) {
        try {
            (void)parseModeRequest(bad);
            ADD_FAILURE() << "accepted \"" << bad << "\"";
        } catch (const DisplayError& e) {
            EXPECT_EQ(std::string(e.what()),
                      "kms: bad mode \"" + bad + "\" (expected WxH or WxH@HZ)");
        }
    }
    DisplayOptions options;
    options.mode = "big";
    EXPECT_EQ(refusal(panel4k(), options), "kms: bad mode \"big\" (expected WxH or WxH@HZ)");
}

TEST(KmsOutputSelection, DpiFromThePanelsWidth) {
    const auto dpi = platform::kms::dpiOf(mode(1920, 1200, 60), 302);
    ASSERT_TRUE(dpi.has_value());
    EXPECT_NEAR(*dpi, 161.5, 0.1);
    EXPECT_FALSE(platform::kms::dpiOf(mode(1920, 1080, 60), 0).has_value());
    EXPECT_FALSE(platform::kms::dpiOf(mode(1920, 1080, 60), 10).has_value()); // 1 cm: nonsense
}

} // namespace
} // namespace steerseg::test
