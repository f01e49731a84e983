// The kiosk's configuration: the shipped file against the built-in defaults, layering key by
// key, and every kind of bad file reported with its file, line and key while the layers below
// stay in force.
#include "config/config_loader.hpp"
#include "config/key_names.hpp"
#include "support/test_data.hpp"

#include <algorithm>
#include <fstream>
#include <gtest/gtest.h>
#include <sstream>

namespace steerseg::test {
namespace {

using config::BindingCheck;
using config::ConfigProblem;
using config::ConfigSource;
using config::KioskConfig;
namespace fs = std::filesystem;

// The workflow's bindable names (app/workflow/action.cpp) as this test's own list: config links
// no workflow code, and the kiosk passes the workflow's real check.
const std::vector<std::string_view> kBindable{
    "run",        "pause",        "toggle_run",    "finish",        "resume",
    "export",     "undo",         "redo",          "restart",       "proceed",
    "back",       "dismiss",      "quit",          "erase_mode:on", "erase_mode:off",
    "select:T",   "select:eps",   "select:alpha",  "select:radius", "cycle_param",
    "nudge:T",    "nudge:eps",    "nudge:alpha",   "nudge:radius",  "nudge_selected",
    "page:axial", "page:coronal", "page:sagittal", "rotate_yaw",    "rotate_pitch",
    "zoom"};
const BindingCheck kCheck = [](std::string_view action) {
    return std::find(kBindable.begin(), kBindable.end(), action) != kBindable.end();
};

std::string readAll(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
}

std::string describeAll(const std::vector<ConfigProblem>& problems) {
    std::string out;
    for (const ConfigProblem& p : problems) {
        out += config::describe(p) + "\n";
    }
    return out;
}

// Names the fields that differ, for a readable failure (operator== decides; it covers fields
// this list might miss).
std::vector<std::string> differences(const KioskConfig& a, const KioskConfig& b) {
    std::vector<std::string> out;
    const auto field = [&out](const char* name, bool same) {
        if (!same) {
            out.emplace_back(name);
        }
    };
    field("display.platform", a.display.platform == b.display.platform);
    field("display.width", a.display.width == b.display.width);
    field("display.height", a.display.height == b.display.height);
    field("display.fullscreen", a.display.fullscreen == b.display.fullscreen);
    field("display.drm_device", a.display.drmDevice == b.display.drmDevice);
    field("display.connector", a.display.connector == b.display.connector);
    field("display.mode", a.display.mode == b.display.mode);
    field("display.rotation", a.display.rotation == b.display.rotation);
    field("display.dpi", a.display.dpi == b.display.dpi);
    field("display.touch_calibration", a.display.touchCalibration == b.display.touchCalibration);
    field("frame.budget_ms", a.frame.budgetMs == b.frame.budgetMs);
    field("frame.solver_share", a.frame.solverShare == b.frame.solverShare);
    field("frame.min_iterations", a.frame.minIterations == b.frame.minIterations);
    field("frame.max_iterations", a.frame.maxIterations == b.frame.maxIterations);
    field("frame.interactive_scale", a.frame.interactiveScale == b.frame.interactiveScale);
    field("ui.touch_target_mm", a.ui.touchTargetMm == b.ui.touchTargetMm);
    field("ui.font_scale", a.ui.fontScale == b.ui.fontScale);
    field("ui.long_press_ms", a.ui.longPressMs == b.ui.longPressMs);
    field("probe.radius_mm", a.probe.radiusMm == b.probe.radiusMm);
    field("probe.eps_factor", a.probe.epsFactor == b.probe.epsFactor);
    field("probe.eps_floor", a.probe.epsFloor == b.probe.epsFloor);
    field("brush.radius", a.brush.radius == b.brush.radius);
    field("brush.correction_reach", a.brush.correctionReach == b.brush.correctionReach);
    field("brush.erase_run_growth", a.brush.eraseRunGrowth == b.brush.eraseRunGrowth);
    field("brush.erase_withdraw_mm", a.brush.eraseWithdrawMm == b.brush.eraseWithdrawMm);
    field("speed.kind", a.speed.kind == b.speed.kind);
    field("speed.classify_within_window",
          a.speed.classifyWithinWindow == b.speed.classifyWithinWindow);
    field("speed.classify_place_reach", a.speed.classifyPlaceReach == b.speed.classifyPlaceReach);
    field("speed.smooth_iterations", a.speed.smoothIterations == b.speed.smoothIterations);
    field("speed.conductance_factor", a.speed.conductanceFactor == b.speed.conductanceFactor);
    field("speed.kappa_factor", a.speed.kappaFactor == b.speed.kappaFactor);
    field("export.folder", a.exports.folder == b.exports.folder);
    field("export.formats", a.exports.formats == b.exports.formats);
    field("audit.path", a.audit.path == b.audit.path);
    field("dicom.tls_certificate", a.dicom.tlsCertificate == b.dicom.tlsCertificate);
    field("dicom.tls_private_key", a.dicom.tlsPrivateKey == b.dicom.tlsPrivateKey);
    field("dicom.tls_ca_certificates", a.dicom.tlsCaCertificates == b.dicom.tlsCaCertificates);
    field("dicom.tls_receive", a.dicom.tlsReceive == b.dicom.tlsReceive);
    field("dicom.search_fields", a.dicom.searchFields == b.dicom.searchFields);
    field("dicom.search_date_presets", a.dicom.searchDatePresets == b.dicom.searchDatePresets);
    field("dicom.query_timeout_seconds",
          a.dicom.queryTimeoutSeconds == b.dicom.queryTimeoutSeconds);
    if (a.presets.size() != b.presets.size()) {
        out.push_back("preset count");
    } else {
        for (std::size_t i = 0; i < a.presets.size(); ++i) {
            const config::Preset& p = a.presets[i];
            const config::Preset& q = b.presets[i];
            const std::string at = "preset[" + std::to_string(i + 1) + "].";
            for (const auto& [name, same] : std::vector<std::pair<std::string, bool>>{
                     {"name", p.name == q.name},
                     {"T", p.T == q.T},
                     {"eps", p.eps == q.eps},
                     {"alpha", p.alpha == q.alpha},
                     {"window_level", p.windowLevel == q.windowLevel},
                     {"window_width", p.windowWidth == q.windowWidth},
                     {"transfer", p.transfer == q.transfer}}) {
                if (!same) {
                    out.push_back(at + name);
                }
            }
        }
    }
    field("segmentation.structures_overlap",
          a.segmentation.structuresOverlap == b.segmentation.structuresOverlap);
    if (a.structures.size() != b.structures.size()) {
        out.push_back("structures count");
    } else {
        for (std::size_t i = 0; i < a.structures.size(); ++i) {
            if (!(a.structures[i] == b.structures[i])) {
                out.push_back("structures[" + std::to_string(i + 1) + "]");
            }
        }
    }
    const auto bindings = [&out](const char* table, const config::BindingTable& x,
                                 const config::BindingTable& y) {
        for (const auto& [key, binding] : x) {
            const auto it = y.find(key);
            if (it == y.end() || !(it->second == binding)) {
                out.push_back(std::string("bindings.") + table + "." + key);
            }
        }
        for (const auto& [key, binding] : y) {
            if (!x.contains(key)) {
                out.push_back(std::string("bindings.") + table + "." + key);
            }
        }
    };
    bindings("keys", a.bindings.keys, b.bindings.keys);
    bindings("knobs", a.bindings.knobs, b.bindings.knobs);
    bindings("buttons", a.bindings.buttons, b.bindings.buttons);
    if (a.input.devices.size() != b.input.devices.size()) {
        out.push_back("input.devices count");
    } else {
        for (std::size_t i = 0; i < a.input.devices.size(); ++i) {
            if (!(a.input.devices[i] == b.input.devices[i])) {
                out.push_back("input.devices[" + std::to_string(i + 1) + "]");
            }
        }
    }
    return out;
}

std::string joined(const std::vector<std::string>& names) {
    std::string out;
    for (const std::string& n : names) {
        out += n + " ";
    }
    return out;
}

class ConfigTest : public ::testing::Test {
  protected:
    fs::path write(const std::string& name, const std::string& text) {
        const fs::path path = dir_ / name;
        std::ofstream(path, std::ios::binary) << text;
        return path;
    }
    config::LoadedConfig load(const std::vector<fs::path>& files) {
        std::vector<ConfigSource> sources;
        for (const fs::path& f : files) {
            sources.push_back({f, true});
        }
        return config::loadConfig(sources, kCheck);
    }
    // One bad file over the defaults: exactly one problem at `line`, naming `key`; the
    // defaults stay in place and the file is not applied.
    void expectRejected(const std::string& text, int line, const std::string& key,
                        const std::string& messagePart) {
        const fs::path path = write("bad.toml", text);
        const config::LoadedConfig loaded = load({path});
        ASSERT_EQ(loaded.problems.size(), 1U) << describeAll(loaded.problems);
        const ConfigProblem& p = loaded.problems.front();
        EXPECT_EQ(p.file, path.string());
        EXPECT_EQ(p.line, line) << config::describe(p);
        EXPECT_GT(p.column, 0) << config::describe(p);
        EXPECT_EQ(p.key, key) << config::describe(p);
        EXPECT_NE(p.message.find(messagePart), std::string::npos) << config::describe(p);
        EXPECT_TRUE(loaded.config == config::defaultConfig())
            << joined(differences(loaded.config, config::defaultConfig()));
        EXPECT_TRUE(loaded.applied.empty());
    }

    void TearDown() override {
        std::error_code ignored;
        fs::remove_all(dir_, ignored);
    }

    fs::path dir_ = tempDir("config_test");
};

TEST_F(ConfigTest, ShippedFileHasNoProblemAndEqualsTheDefaults) {
    const fs::path shipped = STEERSEG_SHIPPED_CONFIG;
    const config::LoadedConfig loaded = load({shipped});
    EXPECT_TRUE(loaded.problems.empty()) << describeAll(loaded.problems);
    ASSERT_EQ(loaded.applied.size(), 1U);
    EXPECT_EQ(loaded.applied.front(), shipped);
    EXPECT_TRUE(differences(loaded.config, config::defaultConfig()).empty())
        << joined(differences(loaded.config, config::defaultConfig()));
    EXPECT_TRUE(loaded.config == config::defaultConfig());
    EXPECT_EQ(loaded.config.presets.size(), 3U);
}

// Applied over a configuration whose every field differs from the defaults, the shipped file
// must give the defaults back: it sets every key, so it documents every key.
TEST_F(ConfigTest, ShippedFileSetsEveryKey) {
    KioskConfig other = config::defaultConfig();
    other.display = {config::DisplayPlatform::Kms,
                     640,
                     480,
                     true,
                     "/dev/dri/card9",
                     "DP-9",
                     "640x480",
                     180,
                     200.0,
                     "2 0 0 0 2 0"};
    other.frame = {50.0, 0.25, 2, 99, 0.75};
    other.ui = {12.0, 2.0, 900};
    other.probe = {7.0, 3.0, 20.0};
    other.brush = {9.0, 1.5, 0.5};
    other.speed = {model::SpeedKind::Edge, 40, 0.5, 0.25, false};
    other.exports = {"elsewhere", {"nrrd"}};
    other.audit = {"elsewhere.jsonl"};
    other.dicom.tlsCertificate = "node.pem";
    other.dicom.tlsPrivateKey = "node.key";
    other.dicom.tlsCaCertificates = "ca.pem";
    other.dicom.tlsReceive = true;
    other.dicom.searchFields = {"accession"};
    other.dicom.searchDatePresets = {};
    other.dicom.queryTimeoutSeconds = 3;
    for (config::Preset& p : other.presets) {
        p = {p.name, p.T + 1, p.eps + 1, p.alpha / 2, p.windowLevel + 1, p.windowWidth + 1, "x"};
    }
    for (config::BindingTable* table :
         {&other.bindings.keys, &other.bindings.knobs, &other.bindings.buttons}) {
        for (auto& [key, binding] : *table) {
            binding = {"quit", 7.0, ""};
        }
    }
    for (config::InputDeviceConfig& d : other.input.devices) {
        d = {d.name + "x", config::InputDeviceKind::GpioLed, 1, 2, 3, 4, "/x", "c", "l", true, 1.0};
    }
    // 39 plain fields, 6 per preset (its name is its identity), every binding.
    ASSERT_EQ(differences(other, config::defaultConfig()).size(),
              39U + 6U * other.presets.size() + other.bindings.keys.size() +
                  other.bindings.knobs.size() + other.bindings.buttons.size() +
                  other.input.devices.size());

    const std::vector<ConfigProblem> problems =
        config::applyConfigText(other, readAll(STEERSEG_SHIPPED_CONFIG), "steerseg.toml", kCheck);
    EXPECT_TRUE(problems.empty()) << describeAll(problems);
    EXPECT_TRUE(other == config::defaultConfig())
        << "not set by the shipped file: " << joined(differences(other, config::defaultConfig()));
}

TEST_F(ConfigTest, LayersOverrideKeyByKey) {
    const fs::path system =
        write("system.toml", "[display]\nrotation = 90\ntouch_calibration = \"0 1 0 -1 0 1\"\n");
    const fs::path user = write("user.toml", "[frame]\nbudget_ms = 50\n"
                                             "[bindings.keys]\nspace = \"run\"\n"
                                             "\"ctrl+z\" = \"none\"\n"
                                             "f5 = { action = \"zoom\", steps = -2.5 }\n");
    const config::LoadedConfig loaded = load({system, user});
    EXPECT_TRUE(loaded.problems.empty()) << describeAll(loaded.problems);
    EXPECT_EQ(loaded.applied, (std::vector<fs::path>{system, user}));

    KioskConfig expected = config::defaultConfig();
    expected.display.rotation = 90;
    expected.display.touchCalibration = "0 1 0 -1 0 1";
    expected.frame.budgetMs = 50.0;
    expected.bindings.keys["space"] = {"run", 1.0, ""};
    expected.bindings.keys.erase("ctrl+z");
    expected.bindings.keys["f5"] = {"zoom", -2.5, ""};
    EXPECT_TRUE(loaded.config == expected) << joined(differences(loaded.config, expected));
}

TEST_F(ConfigTest, TheLaterLayerWinsAndDottedKeysWork) {
    const fs::path system = write("system.toml", "display.rotation = 90\ndisplay.dpi = 160\n");
    const fs::path user = write("user.toml", "[display]\nrotation = 270\n");
    const config::LoadedConfig loaded = load({system, user});
    EXPECT_TRUE(loaded.problems.empty()) << describeAll(loaded.problems);
    EXPECT_EQ(loaded.config.display.rotation, 270);
    EXPECT_EQ(loaded.config.display.dpi, 160.0);
}

TEST_F(ConfigTest, AnEmptyFileIsFine) {
    const fs::path empty = write("empty.toml", "");
    const config::LoadedConfig loaded = load({empty});
    EXPECT_TRUE(loaded.problems.empty()) << describeAll(loaded.problems);
    EXPECT_EQ(loaded.applied.size(), 1U);
    EXPECT_TRUE(loaded.config == config::defaultConfig());
}

TEST_F(ConfigTest, SyntaxError) {
    expectRejected("[display]\nrotation = 90\nwidth = [1,\n", 3, "", "");
}

TEST_F(ConfigTest, UnknownKeyNamesTheKnownOnes) {
    expectRejected("[display]\nwidth = 800\nrotaton = 90\n", 3, "display.rotaton",
                   "unknown key; known here: platform, width");
}

TEST_F(ConfigTest, UnknownSection) {
    expectRejected("\n[dispaly]\nrotation = 90\n", 2, "dispaly", "unknown key");
}

TEST_F(ConfigTest, WrongType) {
    expectRejected("[display]\nwidth = \"wide\"\n", 2, "display.width",
                   "expected an integer, got a string");
    expectRejected("[display]\nwidth = 1280.0\n", 2, "display.width",
                   "expected an integer, got a floating-point number");
    expectRejected("[ui]\nfont_scale = true\n", 2, "ui.font_scale", "expected a number");
    expectRejected("display = 3\n", 1, "display", "expected a table, got an integer");
    expectRejected("[[display]]\nwidth = 3\n", 1, "display", "expected a table, got an array");
}

TEST_F(ConfigTest, OutOfRange) {
    expectRejected("[display]\nrotation = 45\n", 2, "display.rotation",
                   "must be 0, 90, 180 or 270");
    expectRejected("[frame]\nbudget_ms = -5\n", 2, "frame.budget_ms", "is -5; must be at least");
    expectRejected("[ui]\ntouch_target_mm = 8.5\n", 2, "ui.touch_target_mm", "must be at least 9");
    expectRejected("[frame]\nsolver_share = nan\n", 2, "frame.solver_share", "is nan");
    expectRejected("[display]\nwidth = 99999999999999\n", 2, "display.width", "at most 16384");
    expectRejected("[display]\nplatform = \"x11\"\n", 2, "display.platform",
                   "\"auto\", \"kms\", \"window\" or \"offscreen\"");
    expectRejected("[display]\nmode = \"1920x\"\n", 2, "display.mode", "WIDTHxHEIGHT@HZ");
    expectRejected("[display]\ndpi = 10\n", 2, "display.dpi", "at least 50");
    for (const char* matrix : {"1 0 0 0 1", "1 0 0 0 1 0 0", "1 0 0 0 1 x", "1 0 0 0 1 nan",
                               "1,0,0,0,1,0", "1 0 0 0 1 1e999"}) {
        expectRejected("[display]\ntouch_calibration = \"" + std::string(matrix) + "\"\n", 2,
                       "display.touch_calibration", "six numbers");
    }
    expectRejected("[audit]\npath = \"\"\n", 2, "audit.path", "must not be empty");
}

TEST_F(ConfigTest, Speed) {
    const fs::path file = write("speed.toml", "[speed]\nkind = \"edge\"\nsmooth_iterations = 0\n"
                                              "conductance_factor = 0.1\nkappa_factor = 0.5\n"
                                              "classify_within_window = false\n"
                                              "classify_place_reach = 0\n");
    const config::LoadedConfig loaded = load({file});
    EXPECT_TRUE(loaded.problems.empty()) << describeAll(loaded.problems);
    EXPECT_EQ(loaded.config.speed.kind, model::SpeedKind::Edge);
    EXPECT_FALSE(loaded.config.speed.classifyWithinWindow);
    EXPECT_TRUE(config::KioskConfig{}.speed.classifyWithinWindow);
    EXPECT_EQ(loaded.config.speed.classifyPlaceReach, 0.0);
    EXPECT_EQ(config::KioskConfig{}.speed.classifyPlaceReach, 3.0);
    EXPECT_EQ(loaded.config.speed.smoothIterations, 0);
    EXPECT_EQ(loaded.config.speed.conductanceFactor, 0.1);
    EXPECT_EQ(loaded.config.speed.kappaFactor, 0.5);
    expectRejected("[speed]\nkind = \"gradient\"\n", 2, "speed.kind",
                   "must be \"threshold\", \"edge\" or \"classify\"");
    expectRejected("[speed]\nkind = 2\n", 2, "speed.kind", "expected a string");
    expectRejected("[speed]\nclassify_within_window = 1\n", 2, "speed.classify_within_window",
                   "true or false");
    expectRejected("[speed]\nclassify_place_reach = -1\n", 2, "speed.classify_place_reach",
                   "at least 0");
    expectRejected("[brush]\nerase_run_growth = -0.1\n", 2, "brush.erase_run_growth", "at least 0");
    expectRejected("[brush]\nerase_withdraw_mm = -1\n", 2, "brush.erase_withdraw_mm", "at least 0");
    expectRejected("[speed]\nsmooth_iterations = 1001\n", 2, "speed.smooth_iterations",
                   "at most 1000");
    expectRejected("[speed]\nsmooth_iterations = -1\n", 2, "speed.smooth_iterations", "at least 0");
    expectRejected("[speed]\nkappa_factor = 0\n", 2, "speed.kappa_factor", "is 0");
    expectRejected("[speed]\nconductance_factor = 11\n", 2, "speed.conductance_factor",
                   "at most 10");
    expectRejected("[speed]\nkapa_factor = 1\n", 2, "speed.kapa_factor", "unknown key");
}

TEST_F(ConfigTest, DisplayModes) {
    for (const char* mode : {"", "1920x1080", "1920x1080@60", "800x480@144"}) {
        KioskConfig c = config::defaultConfig();
        const auto problems = config::applyConfigText(
            c, std::string("display.mode = \"") + mode + "\"\n", "m.toml", kCheck);
        EXPECT_TRUE(problems.empty()) << mode << ": " << describeAll(problems);
        EXPECT_EQ(c.display.mode, mode);
    }
    for (const char* mode : {"1920", "x1080", "1920x1080@", "1920x1080@60Hz", "0x0", "-1x5",
                             "1920 x 1080", "99999x1"}) {
        KioskConfig c = config::defaultConfig();
        EXPECT_EQ(config::applyConfigText(c, std::string("display.mode = \"") + mode + "\"\n",
                                          "m.toml", kCheck)
                      .size(),
                  1U)
            << mode;
    }
}

TEST_F(ConfigTest, MinIterationsAboveMaxIsReported) {
    expectRejected("[frame]\nmin_iterations = 100\n", 2, "frame.min_iterations",
                   "min_iterations (100) is above max_iterations (64)");
    expectRejected("[frame]\nmin_iterations = 10\nmax_iterations = 5\n", 3, "frame.max_iterations",
                   "is above");
}

TEST_F(ConfigTest, ExportFormats) {
    expectRejected("[export]\nformats = [\"nii.gz\", \"dicom\"]\n", 2, "export.formats[1]",
                   "unknown format \"dicom\"");
    expectRejected("[export]\nformats = [\"nrrd\", \"nrrd\"]\n", 2, "export.formats[1]",
                   "listed twice");
    expectRejected("[export]\nformats = []\n", 2, "export.formats", "at least one format");
    expectRejected("[export]\nformats = \"nrrd\"\n", 2, "export.formats", "expected an array");
    const fs::path good = write("formats.toml", "export.formats = [\"nrrd\", \"nii\"]\n");
    const config::LoadedConfig loaded = load({good});
    EXPECT_TRUE(loaded.problems.empty()) << describeAll(loaded.problems);
    EXPECT_EQ(loaded.config.exports.formats, (std::vector<std::string>{"nrrd", "nii"}));
}

TEST_F(ConfigTest, BadBindings) {
    expectRejected("[bindings.keys]\nspace = \"tooggle_run\"\n", 2, "bindings.keys.space",
                   "\"tooggle_run\" is not an action a control can do");
    expectRejected("[bindings.keys]\n\n\"hyper+q\" = \"quit\"\n", 3, "bindings.keys.\"hyper+q\"",
                   "not a key name");
    expectRejected("[bindings.keys]\nF5 = \"quit\"\n", 2, "bindings.keys.F5", "not a key name");
    expectRejected("[bindings.knobs]\n\"Knob 1\" = \"zoom\"\n", 2, "bindings.knobs.\"Knob 1\"",
                   "not a control name");
    expectRejected("[bindings.buttons]\npedal = 3\n", 2, "bindings.buttons.pedal",
                   "expected an action name");
    expectRejected("[bindings.keys]\nminus = { action = \"zoom\", steps = 0 }\n", 2,
                   "bindings.keys.minus.steps", "must not be 0");
    expectRejected("[bindings.keys]\nminus = { action = \"zoom\", step = 2 }\n", 2,
                   "bindings.keys.minus.step", "unknown key");
    expectRejected("[bindings.keys]\nminus = { steps = 2 }\n", 2, "bindings.keys.minus",
                   "has no action");
    expectRejected("[bindings]\npedals = { pedal = \"run\" }\n", 2, "bindings.pedals",
                   "unknown key; known here: keys, knobs, buttons");
}

TEST_F(ConfigTest, KeyNames) {
    for (const char* name : {"a", "z", "0", "9", "f1", "f12", "space", "pagedown", "ctrl+z",
                             "shift+tab", "ctrl+shift+z", "end"}) {
        EXPECT_TRUE(config::isKeyName(name)) << name;
    }
    for (const char* name : {"", "A", "f0", "f13", "f01", "ctrl+", "shift+ctrl+z", "alt+x",
                             "ctrl+ctrl+z", "spacebar", "insert", " ", "ab"}) {
        EXPECT_FALSE(config::isKeyName(name)) << name;
    }
}

TEST_F(ConfigTest, EveryProblemOfAFileIsReportedAndNoneApplied) {
    const fs::path path = write("many.toml", "[display]\nrotation = 45\nwidth = 1024\n"
                                             "[frame]\nbudget_ms = -1\n"
                                             "[ui]\ntouch_target_mm = 3\ncolour = \"red\"\n");
    const config::LoadedConfig loaded = load({path});
    ASSERT_EQ(loaded.problems.size(), 4U) << describeAll(loaded.problems);
    const std::vector<std::pair<int, std::string>> expected{{2, "display.rotation"},
                                                            {5, "frame.budget_ms"},
                                                            {7, "ui.touch_target_mm"},
                                                            {8, "ui.colour"}};
    for (std::size_t i = 0; i < expected.size(); ++i) {
        EXPECT_EQ(loaded.problems[i].line, expected[i].first) << describeAll(loaded.problems);
        EXPECT_EQ(loaded.problems[i].key, expected[i].second);
    }
    EXPECT_EQ(loaded.config.display.width, 1280) << "the file's good keys must not apply either";
}

TEST_F(ConfigTest, AHostileFileGivesABoundedReport) {
    std::string text = "[ui]\n";
    for (int i = 0; i < 5000; ++i) {
        text += "k" + std::to_string(i) + " = 1\n";
    }
    const config::LoadedConfig loaded = load({write("hostile.toml", text)});
    ASSERT_EQ(loaded.problems.size(), 101U);
    EXPECT_EQ(loaded.problems.back().message, "4900 more problems not listed");
}

TEST_F(ConfigTest, ABadLayerLeavesTheLayersBelow) {
    const fs::path system = write("system.toml", "[display]\nrotation = 90\n");
    const fs::path user = write("user.toml", "[display]\nrotation = 180\nwidth = -1\n");
    const config::LoadedConfig loaded = load({system, user});
    ASSERT_EQ(loaded.problems.size(), 1U) << describeAll(loaded.problems);
    EXPECT_EQ(loaded.problems.front().key, "display.width");
    EXPECT_EQ(loaded.config.display.rotation, 90);
    EXPECT_EQ(loaded.applied, std::vector<fs::path>{system});
}

TEST_F(ConfigTest, MissingFiles) {
    const fs::path missing = dir_ / "nowhere.toml";
    const config::LoadedConfig optional = config::loadConfig({{missing, false}}, kCheck);
    EXPECT_TRUE(optional.problems.empty()) << describeAll(optional.problems);
    EXPECT_TRUE(optional.applied.empty());

    const config::LoadedConfig required = config::loadConfig({{missing, true}}, kCheck);
    ASSERT_EQ(required.problems.size(), 1U);
    EXPECT_EQ(config::describe(required.problems.front()), missing.string() + ": no such file");
    EXPECT_TRUE(required.config == config::defaultConfig());

    const auto sources = config::kioskConfigSources(fs::path("mine.toml"));
    ASSERT_EQ(sources.size(), 2U);
    EXPECT_EQ(sources[0].path, fs::path("/etc/steerseg/steerseg.toml"));
    EXPECT_FALSE(sources[0].required);
    EXPECT_TRUE(sources[1].required);
    EXPECT_EQ(config::kioskConfigSources(std::nullopt).size(), 1U);
}

TEST_F(ConfigTest, AFolderIsNotAConfiguration) {
    const config::LoadedConfig loaded = load({dir_});
    ASSERT_EQ(loaded.problems.size(), 1U);
    EXPECT_EQ(loaded.problems.front().message, "is not a regular file");
}

TEST_F(ConfigTest, HugeFileIsRefusedUnread) {
    std::string text(config::kMaxConfigBytes + 1, '#');
    const fs::path path = write("huge.toml", text);
    const config::LoadedConfig loaded = load({path});
    ASSERT_EQ(loaded.problems.size(), 1U);
    EXPECT_EQ(loaded.problems.front().line, 0);
    EXPECT_NE(loaded.problems.front().message.find("larger than 1 MiB"), std::string::npos);
    // Exactly the limit is still read (a comment is valid TOML).
    text.pop_back();
    EXPECT_TRUE(load({write("limit.toml", text)}).problems.empty());
}

TEST_F(ConfigTest, NonUtf8IsASyntaxErrorWithItsPosition) {
    expectRejected("[audit]\npath = \"caf\xe9.jsonl\"\n", 2, "", "utf-8");
}

TEST_F(ConfigTest, PresetsKeepTheirOrderAndMergeByName) {
    const fs::path path = write("presets.toml", "[[preset]]\nname = \"CT bone\"\nT = 1000\n"
                                                "[[preset]]\nname = \"Liver\"\nT = 60\n"
                                                "eps = 25\nalpha = 0.3\nwindow_level = 60\n"
                                                "window_width = 150\ntransfer = \"soft\"\n");
    const config::LoadedConfig loaded = load({path});
    EXPECT_TRUE(loaded.problems.empty()) << describeAll(loaded.problems);
    std::vector<std::string> names;
    for (const config::Preset& p : loaded.config.presets) {
        names.push_back(p.name);
    }
    EXPECT_EQ(names, (std::vector<std::string>{"CT soft tissue", "CT bone", "MR tumour", "Liver"}));
    config::Preset bone = config::defaultConfig().presets[1];
    bone.T = 1000.0;
    EXPECT_TRUE(loaded.config.presets[1] == bone) << "only the given field changes";
    EXPECT_EQ(loaded.config.presets[3].windowWidth, 150.0);
}

TEST_F(ConfigTest, BadPresets) {
    expectRejected("[[preset]]\nname = \"Liver\"\nT = 60\n", 1, "preset[1]",
                   "new preset \"Liver\" lacks eps, alpha, window_level, window_width, transfer");
    expectRejected("[[preset]]\nT = 60\n", 1, "preset[1]", "has no name");
    expectRejected("[[preset]]\nname = \"CT bone\"\nalpha = 1.5\n", 3, "preset[1].alpha",
                   "at most 1");
    expectRejected("[[preset]]\nname = \"CT bone\"\neps = 0\n", 3, "preset[1].eps", "above 0");
    expectRejected("[[preset]]\nname = \"CT bone\"\nT = inf\n", 3, "preset[1].T", "is inf");
    expectRejected("[[preset]]\nname = \"CT bone\"\ntransfer = \"\"\n", 3, "preset[1].transfer",
                   "must name a transfer function");
    expectRejected("[[preset]]\nname = \"CT bone\"\nT = 1\n[[preset]]\nname = \"CT bone\"\n", 5,
                   "preset[2].name", "given twice");
    expectRejected("[[preset]]\nname = \"CT bone\"\nHU = 1\n", 3, "preset[1].HU", "unknown key");
    expectRejected("preset = [1]\n", 1, "preset[1]", "expected a table");
}

TEST_F(ConfigTest, StructuresReplaceTheSiteListWhole) {
    KioskConfig c = config::defaultConfig();
    const auto problems = config::applyConfigText(
        c,
        "[segmentation]\nstructures_overlap = true\n"
        "[[structures]]\nname = \"Prostate\"\ncategory = [\"123037004\", \"SCT\", "
        "\"Anatomical Structure\"]\ntype = [\"41216001\", \"SCT\", \"Prostate\"]\n"
        "[[structures]]\nname = \"Lesion 1\"\ncategory = [\"49755003\", \"SCT\", \"Morphologically "
        "Abnormal Structure\"]\ntype = [\"52988006\", \"SCT\", \"Lesion\"]\ncolour = [1, 0, 0]\n",
        "s.toml", kCheck);
    ASSERT_TRUE(problems.empty()) << describeAll(problems);
    EXPECT_TRUE(c.segmentation.structuresOverlap);
    ASSERT_EQ(c.structures.size(), 2U);
    EXPECT_EQ(c.structures[0].type.meaning, "Prostate");
    EXPECT_EQ(c.structures[0].colour, model::paletteColour(0)) << "no colour: the palette's";
    EXPECT_EQ(c.structures[1].colour, glm::dvec3(1.0, 0.0, 0.0));
}

TEST_F(ConfigTest, BadStructures) {
    const std::string codes = "category = [\"123037004\", \"SCT\", \"Anatomical Structure\"]\n"
                              "type = [\"10200004\", \"SCT\", \"Liver\"]\n";
    expectRejected("[[structures]]\nname = \"Liver\"\ncategory = [\"1\", \"SCT\"]\n"
                   "type = [\"10200004\", \"SCT\", \"Liver\"]\n",
                   3, "structures[1].category", "three strings");
    expectRejected("[[structures]]\nname = \"Liver\"\ncategory = [\"\", \"SCT\", \"x\"]\n"
                   "type = [\"10200004\", \"SCT\", \"Liver\"]\n",
                   3, "structures[1].category", "needs a value");
    expectRejected("[[structures]]\nname = \"Liver\"\n" + codes +
                       "[[structures]]\nname = \"Liver\"\n" + codes,
                   6, "structures[2].name", "given twice");
    expectRejected("[[structures]]\nname = \"a|b\"\n" + codes, 2, "structures[1].name",
                   "no structure name");
    expectRejected("[[structures]]\nname = \"Liver\"\n" + codes + "colour = [2, 0, 0]\n", 5,
                   "structures[1].colour[1]", "at most 1");
    expectRejected("[[structures]]\nname = \"Liver\"\ntype = [\"10200004\", \"SCT\", \"Liver\"]\n",
                   1, "structures[1].category", "is missing");
}

TEST_F(ConfigTest, DescribeIsOneLine) {
    EXPECT_EQ(config::describe({"a.toml", 3, 7, "display.rotation", "is 45; must be 0"}),
              "a.toml:3:7: display.rotation: is 45; must be 0");
    EXPECT_EQ(config::describe({"a.toml", 0, 0, "", "no such file"}), "a.toml: no such file");
    EXPECT_EQ(config::describe({"a.toml", 1, 1, "", "bad"}), "a.toml:1:1: bad");

    const fs::path path = write("newline.toml", "[bindings.keys]\n\"a\\nb\" = \"run\"\n");
    const config::LoadedConfig loaded = load({path});
    ASSERT_EQ(loaded.problems.size(), 1U);
    const std::string line = config::describe(loaded.problems.front());
    EXPECT_EQ(line.find('\n'), std::string::npos) << line;
    EXPECT_NE(line.find("a\\x0ab"), std::string::npos) << line;
}

TEST_F(ConfigTest, TheBuiltInBindingsAreCheckedToo) {
    const BindingCheck noUndo = [](std::string_view action) {
        return action != "undo" && kCheck(action);
    };
    const config::LoadedConfig loaded = config::loadConfig({}, noUndo);
    // z, ctrl+z, button3 and the two shuttles' undo buttons.
    ASSERT_EQ(loaded.problems.size(), 5U) << describeAll(loaded.problems);
    EXPECT_EQ(loaded.problems[0].file, "built-in defaults");
    EXPECT_EQ(loaded.problems[0].key, "bindings.keys.\"ctrl+z\"");
    EXPECT_FALSE(loaded.config.bindings.keys.contains("z"));
    EXPECT_FALSE(loaded.config.bindings.buttons.contains("button3"));
    EXPECT_TRUE(loaded.config.bindings.keys.contains("space"));
}

TEST_F(ConfigTest, NoBindingCheckIsAProgrammingError) {
    EXPECT_THROW(config::loadConfig({}, BindingCheck{}), std::invalid_argument);
}

TEST_F(ConfigTest, PlatformNames) {
    for (const auto platform :
         {config::DisplayPlatform::Auto, config::DisplayPlatform::Kms,
          config::DisplayPlatform::Window, config::DisplayPlatform::Offscreen}) {
        EXPECT_EQ(config::parsePlatform(config::platformName(platform)), platform);
    }
    EXPECT_FALSE(config::parsePlatform("KMS"));
}

TEST_F(ConfigTest, HoldBindingsOnButtonsOnly) {
    const fs::path good = write("hold.toml", "[bindings.buttons]\n"
                                             "foot = { action = \"run\", release = \"pause\" }\n");
    const config::LoadedConfig loaded = load({good});
    EXPECT_TRUE(loaded.problems.empty()) << describeAll(loaded.problems);
    EXPECT_EQ(loaded.config.bindings.buttons.at("foot"), (config::Binding{"run", 1.0, "pause"}));
    expectRejected("[bindings.buttons]\nfoot = { action = \"run\", release = \"paws\" }\n", 2,
                   "bindings.buttons.foot.release", "\"paws\" is not an action");
    expectRejected("[bindings.knobs]\nring = { action = \"zoom\", release = \"pause\" }\n", 2,
                   "bindings.knobs.ring.release", "unknown key");
    expectRejected("[bindings.buttons]\nfoot = { action = \"run\", release = \"none\" }\n", 2,
                   "bindings.buttons.foot.release", "not a release action");
}

TEST_F(ConfigTest, InputDevicesReplaceTheListAndAcceptHexIds) {
    const fs::path site = write("site.toml", "[[input.devices]]\n"
                                             "name = \"knob\"\n"
                                             "kind = \"shuttle\"\n"
                                             "vendor_id = 0x0b33\n"
                                             "product_id = 0x0030\n"
                                             "[[input.devices]]\n"
                                             "name = \"foot\"\n"
                                             "kind = \"gpio_input\"\n"
                                             "chip = \"gpiochip1\"\n"
                                             "line = \"17\"\n"
                                             "debounce_ms = 5\n");
    const config::LoadedConfig loaded = load({site});
    EXPECT_TRUE(loaded.problems.empty()) << describeAll(loaded.problems);
    ASSERT_EQ(loaded.config.input.devices.size(), 2U);
    const config::InputDeviceConfig& knob = loaded.config.input.devices[0];
    EXPECT_EQ(knob.name, "knob");
    EXPECT_EQ(knob.kind, config::InputDeviceKind::Shuttle);
    EXPECT_EQ(knob.vendorId, 0x0b33);
    EXPECT_EQ(knob.productId, 0x0030);
    const config::InputDeviceConfig& foot = loaded.config.input.devices[1];
    EXPECT_EQ(foot.kind, config::InputDeviceKind::GpioInput);
    EXPECT_EQ(foot.line, "17");
    EXPECT_EQ(foot.debounceMs, 5.0);
    EXPECT_FALSE(foot.activeLow);

    const fs::path none = write("none.toml", "[input]\ndevices = []\n");
    EXPECT_TRUE(load({none}).config.input.devices.empty());
}

TEST_F(ConfigTest, BadInputDevices) {
    const std::string head = "[[input.devices]]\nname = \"k\"\n";
    expectRejected(head + "kind = \"trackball\"\n", 3, "input.devices[1].kind",
                   "must be \"shuttle\"");
    expectRejected(head + "kind = \"shuttle\"\nvendor_id = 0x10000\n", 4,
                   "input.devices[1].vendor_id", "");
    expectRejected(head + "kind = \"shuttle\"\n", 3, "input.devices[1].kind",
                   "needs vendor_id/product_id or usage_page/usage");
    expectRejected(head + "kind = \"shuttle\"\nvendor_id = 1\nchip = \"gpiochip0\"\n", 5,
                   "input.devices[1].chip", "unknown key");
    expectRejected(head + "kind = \"gpio_led\"\nchip = \"gpiochip0\"\nline = \"\"\n", 5,
                   "input.devices[1].line", "must name a GPIO line");
    expectRejected(head + "kind = \"gpio_input\"\nchip = \"c\"\nline = \"L\"\n"
                          "debounce_ms = 5000\n",
                   6, "input.devices[1].debounce_ms", "");
    expectRejected("[[input.devices]]\nname = \"Shuttle 1\"\nkind = \"shuttle\"\n"
                   "vendor_id = 1\n",
                   2, "input.devices[1].name", "a-z, 0-9 and _");
    expectRejected("[[input.devices]]\nname = \"a\"\nkind = \"powermate\"\npath = \"/p\"\n"
                   "[[input.devices]]\nname = \"a\"\nkind = \"powermate\"\npath = \"/q\"\n",
                   6, "input.devices[2].name", "given twice");
}

TEST_F(ConfigTest, DicomNodeAndPeers) {
    const config::LoadedConfig loaded = load({write(
        "dicom.toml", "[dicom]\nenabled = true\naet = \"CONSOLE1\"\nport = 4242\n"
                      "store = \"/srv/in\"\nassociation_quota_mb = 64\nmax_associations = 8\n"
                      "negotiation_seconds = 3\n"
                      "[[dicom.peers]]\nname = \"pacs\"\naet = \"ORTHANC\"\nhost = \"10.0.0.5\"\n"
                      "send = true\nreceive = true\naddress = \"10.0.0.5\"\n"
                      "[[dicom.peers]]\nname = \"ct\"\naet = \"CT_SCANNER\"\nhost = \"ct\"\n"
                      "port = 11112\nreceive = true\n")});
    ASSERT_TRUE(loaded.problems.empty()) << describeAll(loaded.problems);
    const config::DicomConfig& d = loaded.config.dicom;
    EXPECT_TRUE(d.enabled);
    EXPECT_EQ(d.aet, "CONSOLE1");
    EXPECT_EQ(d.maxAssociations, 8);
    EXPECT_EQ(d.negotiationSeconds, 3);
    EXPECT_EQ(d.port, 4242);
    EXPECT_EQ(d.store, fs::path("/srv/in"));
    EXPECT_EQ(d.associationQuotaMb, 64);
    ASSERT_EQ(d.peers.size(), 2U);
    EXPECT_EQ(d.peers[0], (config::DicomPeerConfig{"pacs", "ORTHANC", "10.0.0.5", 104, "10.0.0.5",
                                                   true, true}));
    EXPECT_EQ(d.peers[1].port, 11112);
    EXPECT_FALSE(d.peers[1].send);
    EXPECT_FALSE(d.peers[0].query); // asked only where a site says so
    EXPECT_EQ(d.peers[0].retrieve, config::DicomPeerConfig::Retrieve::Get);
    EXPECT_FALSE(config::defaultConfig().dicom.enabled); // off unless a site turns it on
}

TEST_F(ConfigTest, DicomQueryPeers) {
    const config::LoadedConfig loaded = load({write(
        "query.toml", "[[dicom.peers]]\nname = \"pacs\"\naet = \"ORTHANC\"\nhost = \"pacs\"\n"
                      "query = true\nretrieve = \"move\"\n"
                      "[[dicom.peers]]\nname = \"vna\"\naet = \"VNA\"\nhost = \"vna\"\n"
                      "query = true\nretrieve = \"get\"\n")});
    ASSERT_TRUE(loaded.problems.empty()) << describeAll(loaded.problems);
    const auto& peers = loaded.config.dicom.peers;
    ASSERT_EQ(peers.size(), 2U);
    // A peer that is only queried is a peer: neither receive nor send needed.
    EXPECT_TRUE(peers[0].query);
    EXPECT_FALSE(peers[0].receive || peers[0].send);
    EXPECT_EQ(peers[0].retrieve, config::DicomPeerConfig::Retrieve::Move);
    EXPECT_EQ(peers[1].retrieve, config::DicomPeerConfig::Retrieve::Get);

    const std::string peer = "[[dicom.peers]]\nname = \"pacs\"\naet = \"PACS\"\nhost = \"h\"\n";
    expectRejected(peer + "query = true\nretrieve = \"fetch\"\n", 6, "dicom.peers[1].retrieve",
                   "must be \"get\" or \"move\"");
    expectRejected(peer + "query = true\nretrieve = 1\n", 6, "dicom.peers[1].retrieve",
                   "expected a string");
    expectRejected(peer + "query = \"yes\"\nsend = true\n", 5, "dicom.peers[1].query",
                   "expected true or false");
    expectRejected(peer + "query = false\n", 1, "dicom.peers[1].receive", "query = true");
}

// The kiosk's PACS search form: the fields and date chips a site turns on, by name.
TEST_F(ConfigTest, SearchFieldsAndDatePresetsAreReadAndCheckedByName) {
    const fs::path good = write("good.toml", "[dicom]\nsearch_fields = [\"accession\", "
                                             "\"patient_id\"]\nsearch_date_presets = []\n"
                                             "query_timeout_seconds = 4\n");
    const config::LoadedConfig loaded = load({good});
    ASSERT_TRUE(loaded.problems.empty()) << describeAll(loaded.problems);
    EXPECT_EQ(loaded.config.dicom.searchFields,
              (std::vector<std::string>{"accession", "patient_id"}));
    EXPECT_TRUE(loaded.config.dicom.searchDatePresets.empty());
    EXPECT_EQ(loaded.config.dicom.queryTimeoutSeconds, 4);
    expectRejected("[dicom]\nsearch_fields = [\"patient_id\", \"birth_date\"]\n", 2,
                   "dicom.search_fields[1]",
                   "unknown name \"birth_date\"; known: patient_name, patient_id, study_date, "
                   "modality, accession");
    expectRejected("[dicom]\nsearch_fields = [\"modality\", \"modality\"]\n", 2,
                   "dicom.search_fields[1]", "listed twice");
    expectRejected("[dicom]\nsearch_fields = []\n", 2, "dicom.search_fields",
                   "must name at least one");
    expectRejected("[dicom]\nsearch_date_presets = [\"last_week\"]\n", 2,
                   "dicom.search_date_presets[0]", "known: any, today, yesterday");
    expectRejected("[dicom]\nquery_timeout_seconds = 0\n", 2, "dicom.query_timeout_seconds",
                   "at least 1");
}

TEST_F(ConfigTest, BadDicomValuesAreRefusedWithTheirPlace) {
    expectRejected("[dicom]\naet = \"THIS-IS-TOO-LONG-X\"\n", 2, "dicom.aet", "1 to 16");
    expectRejected("[dicom]\naet = \"A\\\\B\"\n", 2, "dicom.aet", "no backslash");
    expectRejected("[dicom]\nport = 70000\n", 2, "dicom.port", "at most 65535");
    expectRejected("[dicom]\nport = \"104\"\n", 2, "dicom.port", "expected an integer");
    expectRejected("[dicom]\nstore = \"\"\n", 2, "dicom.store", "must not be empty");
    expectRejected("[dicom]\nassociation_quota_mb = 0\n", 2, "dicom.association_quota_mb",
                   "at least 1");
    expectRejected("[dicom]\nmax_associations = 0\n", 2, "dicom.max_associations", "at least 1");
    expectRejected("[dicom]\nnegotiation_seconds = 61\n", 2, "dicom.negotiation_seconds",
                   "at most 60");
    expectRejected("[dicom]\ntls = true\n", 2, "dicom.tls", "set per peer");
    expectRejected("[dicom]\nlisten = true\n", 2, "dicom.listen", "");
    expectRejected("[[dicom.peers]]\nname = \"pacs\"\naet = \"PACS\"\nhost = \"pacs host\"\n"
                   "send = true\n",
                   4, "dicom.peers[1].host", "without blanks");
    expectRejected("[[dicom.peers]]\nname = \"pacs\"\naet = \"PACS\"\nhost = \"h\"\n", 1,
                   "dicom.peers[1].receive", "receive = true");
    expectRejected("[[dicom.peers]]\nname = \"pacs\"\naet = \"PACS\"\nsend = true\n", 1,
                   "dicom.peers[1].host", "is missing");
    expectRejected("[[dicom.peers]]\nname = \"a\"\naet = \"A\"\nhost = \"h\"\nsend = true\n"
                   "[[dicom.peers]]\nname = \"a\"\naet = \"B\"\nhost = \"h\"\nsend = true\n",
                   7, "dicom.peers[2].name", "given twice");
}

// The TLS keys name files that must be there and hold PEM of their kind (whether they load
// and match is the self-test's: tests/cli), and TLS is asked for only with all three.
TEST_F(ConfigTest, DicomTlsFilesAndRelations) {
    const std::string cert = "-----BEGIN CERTIFICATE-----\nMIIB\n-----END CERTIFICATE-----\n";
    const fs::path ca = write("ca.pem", cert);
    const fs::path node = write("node.pem", cert);
    const fs::path key =
        write("node.key", "-----BEGIN PRIVATE KEY-----\nMIIE\n-----END PRIVATE KEY-----\n");
    const fs::path encrypted =
        write("enc.key",
              "-----BEGIN ENCRYPTED PRIVATE KEY-----\nMIIF\n-----END ENCRYPTED PRIVATE KEY-----\n");
    const auto files = [&](const fs::path& c, const fs::path& k, const fs::path& t) {
        return "[dicom]\ntls_certificate = \"" + c.string() + "\"\ntls_private_key = \"" +
               k.string() + "\"\ntls_ca_certificates = \"" + t.string() + "\"\n";
    };
    const std::string peer = "[[dicom.peers]]\nname = \"pacs\"\naet = \"PACS\"\nhost = \"h\"\n";

    const config::LoadedConfig good =
        load({write("tls.toml", files(node, key, ca) + "tls_receive = true\n" + peer +
                                    "receive = true\nsend = true\ntls = true\n")});
    ASSERT_TRUE(good.problems.empty()) << describeAll(good.problems);
    EXPECT_EQ(good.config.dicom.tlsCertificate, node);
    EXPECT_EQ(good.config.dicom.tlsPrivateKey, key);
    EXPECT_EQ(good.config.dicom.tlsCaCertificates, ca);
    EXPECT_TRUE(good.config.dicom.tlsReceive);
    EXPECT_TRUE(good.config.dicom.peers.at(0).tls);
    // A folder of CA certificates will do.
    const config::LoadedConfig folder = load({write("folder.toml", files(node, key, dir_))});
    EXPECT_TRUE(folder.problems.empty()) << describeAll(folder.problems);

    expectRejected(files(dir_ / "none.pem", key, ca), 2, "dicom.tls_certificate", "no such file");
    expectRejected(files(node, encrypted, ca), 3, "dicom.tls_private_key", "is encrypted");
    expectRejected(files(node, node, ca), 3, "dicom.tls_private_key", "no PEM private key");
    expectRejected(files(node, key, key), 4, "dicom.tls_ca_certificates", "no PEM certificate");
    expectRejected(peer + "send = true\ntls = true\n", 6, "dicom.peers[1].tls", "TLS needs");
    expectRejected("[dicom]\ntls_receive = true\n", 2, "dicom.tls_receive", "TLS needs");
    expectRejected(files(node, key, ca) + "tls_receive = true\n" + peer + "receive = true\n", 6,
                   "dicom.peers[1].tls", "could not call");
    expectRejected(files(node, key, ca) + peer + "receive = true\ntls = true\n", 10,
                   "dicom.peers[1].tls", "tls_receive = true");
    // A C-MOVE's images come on an association the peer opens to the node's port.
    expectRejected(files(node, key, ca) + peer + "query = true\nretrieve = \"move\"\ntls = true\n",
                   11, "dicom.peers[1].tls", "retrieve = \"move\" over TLS");
    EXPECT_TRUE(load({write("get.toml", files(node, key, ca) + peer +
                                            "query = true\nretrieve = \"get\"\ntls = true\n")})
                    .problems.empty());
}

TEST(ConfigNames, InputDeviceKindsRoundTrip) {
    for (const auto kind : {config::InputDeviceKind::Shuttle, config::InputDeviceKind::Radial,
                            config::InputDeviceKind::PowerMate, config::InputDeviceKind::GpioInput,
                            config::InputDeviceKind::GpioLed}) {
        EXPECT_EQ(config::parseInputDeviceKind(config::inputDeviceKindName(kind)), kind);
    }
    EXPECT_FALSE(config::parseInputDeviceKind("Shuttle"));
}

} // namespace
} // namespace steerseg::test
