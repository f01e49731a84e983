// A tap on a slice view lands on the voxel under the finger, through the whole kiosk: the
// display's physical pixels, the panel's rotation, the layout, the slice picture actually on
// screen and its frame, the gesture, the workflow, the audit log. For each orientation in the
// first slice view and a display mounted upright and a quarter turn.
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

// The voxel-index centre the kiosk's audit log recorded for the session's one seed.
std::optional<glm::dvec3> seedInAuditLog(const std::filesystem::path& log) {
    std::ifstream in(log);
    std::string line;
    while (std::getline(in, line)) {
        const nlohmann::json j = nlohmann::json::parse(line, nullptr, false);
        if (j.is_object() && j.value("action", "") == "add_seed" && j.value("accepted", false)) {
            const auto& v = j["values"]["voxel"];
            return glm::dvec3(v[0].get<double>(), v[1].get<double>(), v[2].get<double>());
        }
    }
    return std::nullopt;
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

    std::ofstream(dir / "kiosk.toml")
        << "[display]\nrotation = " << c.rotation << "\ndpi = " << dpi << "\n[audit]\npath = \""
        << (dir / "audit.jsonl").string() << "\"\n[export]\nfolder = \"" << dir.string() << "\"\n";
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
    std::ofstream(dir / "touch.session") << script.str();

    kiosk::KioskOptions options;
    options.platform = "offscreen";
    options.config = dir / "kiosk.toml";
    options.script = dir / "touch.session";
    options.width = physical.x;
    options.height = physical.y;
    options.maxSeconds = 60.0;
    std::ostringstream out;
    std::ostringstream err;
    ASSERT_EQ(kiosk::runKiosk(options, out, err), 0) << err.str();
    const std::optional<glm::dvec3> seed = seedInAuditLog(dir / "audit.jsonl");
    ASSERT_TRUE(seed.has_value()) << "no seed in the audit log; stderr: " << err.str();
    // Within half a voxel in the slice's plane, on the slice itself across it.
    for (int a = 0; a < 3; ++a) {
        EXPECT_NEAR((*seed)[a], target[a], a == sliceAxis ? 1e-9 : 0.5)
            << c.axisName << " at " << c.rotation << " degrees, axis " << a;
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
