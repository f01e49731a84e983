// A tap on a slice view lands on the voxel under the finger, through the whole kiosk: the
// display's physical pixels, the panel's rotation, the layout, the slice picture actually on
// screen and its frame, the gesture, the workflow, the audit log. For each orientation in the
// first slice view and a display mounted upright and a quarter turn. And a drag paints a stroke
// along the finger's path.
#include "core/sample_phantom.hpp"
#include "engine/view_setup.hpp"
#include "kiosk/kiosk_app.hpp"
#include "render/slice_frame.hpp"
#include "ui/layout.hpp"
#include "ui/screen_rotation.hpp"
#include "ui/slice_mapping.hpp"

#include <filesystem>
#include <fstream>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>
#include <sstream>

namespace steerseg::test {
namespace {

struct Case {
    model::SliceAxis axis;
    const char* axisName;
    int rotation;
};

class KioskTouch : public ::testing::TestWithParam<Case> {};

// The values of the first accepted `action` in the kiosk's audit log.
std::optional<nlohmann::json> acceptedInAuditLog(const std::filesystem::path& log,
                                                 const std::string& action) {
    std::ifstream in(log);
    std::string line;
    while (std::getline(in, line)) {
        const nlohmann::json j = nlohmann::json::parse(line, nullptr, false);
        if (j.is_object() && j.value("action", "") == action && j.value("accepted", false)) {
            return j["values"];
        }
    }
    return std::nullopt;
}

glm::dvec3 voxelOf(const nlohmann::json& v) {
    return {v[0].get<double>(), v[1].get<double>(), v[2].get<double>()};
}

// The voxel-index centre the kiosk's audit log recorded for the session's one seed.
std::optional<glm::dvec3> seedInAuditLog(const std::filesystem::path& log) {
    const std::optional<nlohmann::json> values = acceptedInAuditLog(log, "add_seed");
    return values ? std::optional(voxelOf((*values)["voxel"])) : std::nullopt;
}

// Runs the kiosk offscreen on a physical screen of `physical` pixels mounted at `rotation`,
// with an audit log in `dir`, playing `script`.
void runKioskSession(const std::filesystem::path& dir, int rotation, double dpi,
                     const glm::ivec2& physical, const std::string& script, std::string& err) {
    std::ofstream(dir / "kiosk.toml")
        << "[display]\nrotation = " << rotation << "\ndpi = " << dpi << "\n[audit]\npath = \""
        << (dir / "audit.jsonl").string() << "\"\n[export]\nfolder = \"" << dir.string() << "\"\n";
    std::ofstream(dir / "touch.session") << script;
    kiosk::KioskOptions options;
    options.platform = "offscreen";
    options.config = dir / "kiosk.toml";
    options.script = dir / "touch.session";
    options.width = physical.x;
    options.height = physical.y;
    options.maxSeconds = 60.0;
    std::ostringstream out;
    std::ostringstream errors;
    EXPECT_EQ(kiosk::runKiosk(options, out, errors), 0) << errors.str();
    err = errors.str();
}

TEST_P(KioskTouch, ATapSeedsTheVoxelUnderTheFinger) {
    const Case c = GetParam();
    const glm::ivec2 physical(640, 400);
    const double dpi = 96.0;
    const auto dir =
        std::filesystem::temp_directory_path() /
        ("steerseg_kiosk_touch_" + std::string(c.axisName) + std::to_string(c.rotation));
    std::filesystem::remove_all(dir);
    std::filesystem::create_directories(dir);

    // Where the kiosk will show the first slice view, and the voxel to aim at: the lesion's
    // centre, off the slice's middle in every direction.
    const ui::ScreenRotation rotation(c.rotation, physical.x, physical.y);
    const glm::ivec2 logical = rotation.logicalSize();
    const ui::Layout layout = ui::computeLayout(logical.x, logical.y, dpi);
    const Geometry geometry = makeSamplePhantom().geometry();
    const glm::dvec3 target(80.0, 56.0, 52.0);
    render::ViewParams params;
    params.kind = engine::viewKindOf(c.axis);
    params.size = {layout.slice1.w, layout.slice1.h};
    const int sliceAxis = render::sliceAxisFor(geometry, params.kind);
    params.slice = static_cast<int>(target[sliceAxis]);
    const ui::SliceView view{render::sliceFrame(geometry, params), params.size, layout.slice1};
    const glm::dvec2 onScreen = ui::screenOfVoxel(view, target);
    const glm::dvec2 finger = rotation.toPhysical(onScreen);

    std::ostringstream script;
    script << "load builtin:sample\nwait loaded\n"
           << "show " << c.axisName
           << (c.axis == model::SliceAxis::Coronal ? " axial\n" : " coronal\n") << "slice "
           << c.axisName << " " << params.slice << "\n"
           << "proceed\nwait state seeding\n"
           // A frame is written once every view is complete at full resolution, and the script
           // waits for it: the tap then lands on the full picture, however slow the machine.
           << "frame " << (dir / "before-tap.png").string() << "\n"
           << "tap " << finger.x << " " << finger.y << "\n"
           << "wait seconds 1\nexpect seeds == 1\n";
    std::string err;
    runKioskSession(dir, c.rotation, dpi, physical, script.str(), err);
    const std::optional<glm::dvec3> seed = seedInAuditLog(dir / "audit.jsonl");
    ASSERT_TRUE(seed.has_value()) << "no seed in the audit log; stderr: " << err;
    // Within half a voxel in the slice's plane, on the slice itself across it.
    for (int a = 0; a < 3; ++a) {
        EXPECT_NEAR((*seed)[a], target[a], a == sliceAxis ? 1e-9 : 0.5)
            << c.axisName << " at " << c.rotation << " degrees, axis " << a;
    }
    std::filesystem::remove_all(dir);
}

// A one-finger drag across the first (axial) slice view in seeding paints one stroke along the
// path under the finger, through the same kiosk; one undo takes it back.
TEST(KioskStroke, ADragPaintsAStrokeAlongTheFinger) {
    const glm::ivec2 physical(640, 400);
    const double dpi = 96.0;
    const auto dir = std::filesystem::temp_directory_path() / "steerseg_kiosk_stroke";
    std::filesystem::remove_all(dir);
    std::filesystem::create_directories(dir);
    const ui::Layout layout = ui::computeLayout(physical.x, physical.y, dpi);
    const Geometry geometry = makeSamplePhantom().geometry();
    render::ViewParams params;
    params.kind = render::ViewKind::Axial;
    params.size = {layout.slice1.w, layout.slice1.h};
    params.slice = 52;
    const ui::SliceView view{render::sliceFrame(geometry, params), params.size, layout.slice1};
    const int sliceAxis = render::sliceAxisFor(geometry, params.kind);
    // Across the lesion, on the shown slice.
    glm::dvec3 from(60.0, 50.0, 48.0);
    glm::dvec3 to(100.0, 62.0, 60.0);
    from[sliceAxis] = to[sliceAxis] = 52.0;
    std::ostringstream script;
    script << "load builtin:sample\nwait loaded\nshow axial coronal\nslice axial 52\n"
           << "proceed\nwait state seeding\n"
           << "frame " << (dir / "before-drag.png").string() << "\n";
    const glm::dvec2 down = ui::screenOfVoxel(view, from);
    script << "touch down 0 " << down.x << " " << down.y << "\n";
    for (int m = 1; m <= 4; ++m) {
        const glm::dvec2 p = ui::screenOfVoxel(view, from + (to - from) * (m / 4.0));
        script << "touch move 0 " << p.x << " " << p.y << "\n";
    }
    const glm::dvec2 up = ui::screenOfVoxel(view, to);
    script << "touch up 0 " << up.x << " " << up.y << "\n"
           << "wait seconds 1\nexpect seeds == 1\nundo\nwait seconds 0.5\nexpect seeds == 0\n";
    std::string err;
    runKioskSession(dir, 0, dpi, physical, script.str(), err);
    const std::optional<nlohmann::json> stroke =
        acceptedInAuditLog(dir / "audit.jsonl", "paint_stroke");
    ASSERT_TRUE(stroke.has_value()) << "no stroke in the audit log; stderr: " << err;
    EXPECT_EQ((*stroke)["mode"], "add");
    EXPECT_EQ((*stroke)["point_count"], 5) << "where it went down and each move";
    const glm::dvec3 first = voxelOf((*stroke)["points"].front());
    const glm::dvec3 last = voxelOf((*stroke)["points"].back());
    for (int a = 0; a < 3; ++a) {
        EXPECT_NEAR(first[a], from[a], a == sliceAxis ? 1e-9 : 0.5) << "axis " << a;
        EXPECT_NEAR(last[a], to[a], a == sliceAxis ? 1e-9 : 0.5) << "axis " << a;
    }
    std::filesystem::remove_all(dir);
}

INSTANTIATE_TEST_SUITE_P(OrientationsAndMountings, KioskTouch,
                         ::testing::Values(Case{model::SliceAxis::Axial, "axial", 0},
                                           Case{model::SliceAxis::Coronal, "coronal", 0},
                                           Case{model::SliceAxis::Sagittal, "sagittal", 0},
                                           Case{model::SliceAxis::Axial, "axial", 90},
                                           Case{model::SliceAxis::Coronal, "coronal", 270},
                                           Case{model::SliceAxis::Sagittal, "sagittal", 180}),
                         [](const ::testing::TestParamInfo<Case>& param) {
                             return std::string(param.param.axisName) +
                                    std::to_string(param.param.rotation);
                         });

} // namespace
} // namespace steerseg::test
