// A tap on a slice view lands on the voxel under the finger, through the whole kiosk: the
// display's physical pixels, the panel's rotation, the layout, the slice picture actually on
// screen and its frame, the gesture, the workflow, the audit log. For each orientation in the
// first slice view and a display mounted upright and a quarter turn. And a drag paints a stroke
// along the finger's path; in box mode two drags draw the box, which holds the run's mask.
#include "core/sample_phantom.hpp"
#include "engine/view_setup.hpp"
#include "kiosk/kiosk_app.hpp"
#include "model/box.hpp"
#include "render/slice_frame.hpp"
#include "scan/scan_reader.hpp"
#include "ui/layout.hpp"
#include "ui/screen_rotation.hpp"
#include "ui/slice_mapping.hpp"

#include <algorithm>
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

// The `touch` steps of a one-finger drag from `from` to `to` (voxels) on `view`.
std::string dragSteps(const ui::SliceView& view, const glm::dvec3& from, const glm::dvec3& to) {
    std::ostringstream s;
    const glm::dvec2 down = ui::screenOfVoxel(view, from);
    s << "touch down 0 " << down.x << " " << down.y << "\n";
    for (int m = 1; m <= 4; ++m) {
        const glm::dvec2 p = ui::screenOfVoxel(view, from + (to - from) * (m / 4.0));
        s << "touch move 0 " << p.x << " " << p.y << "\n";
    }
    const glm::dvec2 up = ui::screenOfVoxel(view, to);
    s << "touch up 0 " << up.x << " " << up.y << "\n";
    return s.str();
}

model::Box boxInAuditLog(const nlohmann::json& values) {
    model::Box b;
    for (int a = 0; a < 3; ++a) {
        b.lo[a] = values["lo"][static_cast<std::size_t>(a)].get<int>();
        b.hi[a] = values["hi"][static_cast<std::size_t>(a)].get<int>();
    }
    return b;
}

// Box mode through the whole kiosk: a drag on the axial view draws the box across the lesion
// (i and j; k as deep as its smaller side, 21 mm, centred on the slice), which probes and
// seeds; a drag on the coronal view, begun beside the box's rectangle (not on an edge: that
// would move a face), sets i and k. The run's exported mask lies in the box (the box cuts the
// lesion, so without it the mask would not), and undo takes the boxes back.
TEST(KioskBox, TwoDragsDrawTheBoxAndTheRunStaysInIt) {
    const glm::ivec2 physical(640, 400);
    const double dpi = 96.0;
    const auto dir = std::filesystem::temp_directory_path() / "steerseg_kiosk_box";
    std::filesystem::remove_all(dir);
    std::filesystem::create_directories(dir);
    const ui::Layout layout = ui::computeLayout(physical.x, physical.y, dpi);
    const Geometry geometry = makeSamplePhantom().geometry();
    const auto viewOf = [&](render::ViewKind kind, int slice, const ui::Rect& rect) {
        render::ViewParams params;
        params.kind = kind;
        params.size = {rect.w, rect.h};
        params.slice = slice;
        return ui::SliceView{render::sliceFrame(geometry, params), params.size, rect};
    };
    const ui::SliceView axial = viewOf(render::ViewKind::Axial, 52, layout.slice1);
    const ui::SliceView coronal = viewOf(render::ViewKind::Coronal, 56, layout.slice2);
    ASSERT_EQ(axial.frame.sliceAxis, 2);
    ASSERT_EQ(coronal.frame.sliceAxis, 1);
    const model::Box drawn{{72, 46, 46}, {92, 66, 59}};  // the lesion spans 68..92, 44..68
    const model::Box second{{62, 46, 38}, {84, 66, 56}}; // ... and k 44..60
    const auto mask = dir / "mask.nii.gz";
    std::ostringstream script;
    script << "load builtin:sample\nwait loaded\nshow axial coronal\nslice axial 52\n"
           << "slice coronal 56\nspeed threshold\nbox_mode on\nexpect box_mode == 1\n"
           << "frame " << (dir / "before-box.png").string() << "\n"
           << dragSteps(axial, {72.0, 46.0, 52.0}, {92.0, 66.0, 52.0})
           << "wait state seeding\nexpect has_box == 1\nexpect seeds == 1\n"
           << "frame " << (dir / "first-box.png").string() << "\n"
           << dragSteps(coronal, {62.0, 56.0, 38.0}, {84.0, 56.0, 56.0})
           << "wait seconds 0.5\nrun\nwait state evolving\nwait seconds 3\npause\n"
           << "expect has_level_set == 1\nexport " << mask.string() << "\nwait state done\n"
           << "back\nresume\nwait state paused\nundo\nexpect has_box == 1\nundo\n"
           << "expect has_box == 0\n";
    std::string err;
    runKioskSession(dir, 0, dpi, physical, script.str(), err);

    // One set_box a drag, each with the box the finger drew.
    std::vector<model::Box> boxes;
    std::ifstream in(dir / "audit.jsonl");
    std::string line;
    while (std::getline(in, line)) {
        const nlohmann::json j = nlohmann::json::parse(line, nullptr, false);
        if (j.is_object() && j.value("action", "") == "set_box") {
            EXPECT_TRUE(j.value("accepted", false)) << line;
            boxes.push_back(boxInAuditLog(j["values"]));
        }
    }
    ASSERT_EQ(boxes.size(), 2U) << "stderr: " << err;
    EXPECT_EQ(boxes[0], drawn) << model::describe(boxes[0]);
    EXPECT_EQ(boxes[1], second) << model::describe(boxes[1]);

    ASSERT_TRUE(std::filesystem::exists(mask)) << "stderr: " << err;
    const Volume m = scan::readScan(mask).volume;
    ASSERT_EQ(m.geometry().dims, geometry.dims);
    std::size_t inside = 0;
    std::size_t outsideTheBox = 0;
    int reach = 0; // the mask's largest i
    for (int k = 0; k < geometry.dims.z; ++k) {
        for (int j = 0; j < geometry.dims.y; ++j) {
            for (int i = 0; i < geometry.dims.x; ++i) {
                if (m.valueAt(i, j, k) != 0.0) {
                    ++inside;
                    outsideTheBox += model::contains(second, {i, j, k}) ? 0 : 1;
                    reach = std::max(reach, i);
                }
            }
        }
    }
    EXPECT_GT(inside, 1000U) << "the run grew the lesion";
    EXPECT_EQ(outsideTheBox, 0U);
    EXPECT_GE(reach, second.hi.x - 1) << "the run reached the box's face: the box held it";
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
