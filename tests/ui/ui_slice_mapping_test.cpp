#include "core/volume.hpp"
#include "render/slice_frame.hpp"
#include "ui/screen_rotation.hpp"
#include "ui/slice_mapping.hpp"

#include <cmath>
#include <glm/gtc/matrix_transform.hpp>
#include <gtest/gtest.h>
#include <string>
#include <vector>

namespace steerseg::test {

namespace {

struct Case {
    std::string name;
    Geometry geometry;
};

Geometry baseGeometry() {
    Geometry g;
    g.dims = {40, 52, 30};
    g.spacing = {1.0, 0.8, 2.5};
    g.origin = {-20.0, 10.0, 5.0};
    return g;
}

std::vector<Case> geometries() {
    std::vector<Case> cases;
    cases.push_back({"identity", baseGeometry()});
    Geometry flipped = baseGeometry();
    // i runs to the patient's right, j is the slice axis (feet to head), k runs posterior.
    flipped.direction = glm::dmat3(glm::dvec3(-1, 0, 0), glm::dvec3(0, 0, 1), glm::dvec3(0, 1, 0));
    cases.push_back({"flipped_permuted", flipped});
    Geometry oblique = baseGeometry();
    oblique.direction =
        glm::dmat3(glm::rotate(glm::dmat4(1.0), glm::radians(12.0), glm::dvec3(0.3, 1.0, 0.2)));
    cases.push_back({"oblique", oblique});
    return cases;
}

ui::SliceView viewOf(const Geometry& g, render::ViewKind kind, glm::ivec2 renderSize, ui::Rect rect,
                     int slice = -1) {
    render::ViewParams p;
    p.kind = kind;
    p.size = renderSize;
    p.slice = slice;
    return {render::sliceFrame(g, p), renderSize, rect};
}

const char* kindName(render::ViewKind k) {
    switch (k) {
    case render::ViewKind::Axial:
        return "axial";
    case render::ViewKind::Coronal:
        return "coronal";
    case render::ViewKind::Sagittal:
        return "sagittal";
    case render::ViewKind::Volume3d:
        break;
    }
    return "3d";
}

// Screen right and screen up in world LPS for each view (radiological convention, as
// render/slice_frame.hpp states it).
void screenAxes(render::ViewKind k, glm::dvec3& right, glm::dvec3& up) {
    switch (k) {
    case render::ViewKind::Axial:
        right = {1, 0, 0};
        up = {0, -1, 0};
        return;
    case render::ViewKind::Coronal:
        right = {1, 0, 0};
        up = {0, 0, 1};
        return;
    default:
        right = {0, 1, 0};
        up = {0, 0, 1};
        return;
    }
}

const render::ViewKind kKinds[] = {render::ViewKind::Axial, render::ViewKind::Coronal,
                                   render::ViewKind::Sagittal};
// Rendered at half the shown size (the kiosk may render slices at a lower resolution).
const glm::ivec2 kRender{150, 120};
const ui::Rect kRect{930, 410, 300, 240};

} // namespace

// The image pixel (x, y) shows the voxel origin + x * stepRight + y * stepDown: a tap in the
// middle of the screen area of that image pixel must land on that voxel position.
TEST(UiSliceMapping, TapOnAnImagePixelGivesItsVoxel) {
    for (const Case& c : geometries()) {
        for (render::ViewKind kind : kKinds) {
            SCOPED_TRACE(c.name + " " + kindName(kind));
            const ui::SliceView v = viewOf(c.geometry, kind, kRender, kRect);
            for (int x : {0, 17, 75, 149}) {
                for (int y : {0, 33, 60, 119}) {
                    const glm::dvec2 tap(kRect.x + (x + 0.5) * 2.0, kRect.y + (y + 0.5) * 2.0);
                    const auto voxel = ui::voxelAtScreen(v, tap);
                    ASSERT_TRUE(voxel);
                    const glm::dvec3 expected = v.frame.origin + double(x) * v.frame.stepRight +
                                                double(y) * v.frame.stepDown;
                    EXPECT_NEAR(glm::length(*voxel - expected), 0.0, 1e-9);
                    EXPECT_EQ((*voxel)[v.frame.sliceAxis], v.frame.slice);
                }
            }
        }
    }
}

// A voxel's projection lies within half a screen pixel of the tap that finds it, so the voxel
// under the finger is the one drawn there.
TEST(UiSliceMapping, EveryVoxelOnTheSliceProjectsUnderTheTap) {
    for (const Case& c : geometries()) {
        for (render::ViewKind kind : kKinds) {
            SCOPED_TRACE(c.name + " " + kindName(kind));
            const ui::SliceView v = viewOf(c.geometry, kind, kRender, kRect, 7);
            const glm::ivec3 dims = c.geometry.dims;
            int checked = 0;
            for (int a = 0; a < dims[v.frame.axisU]; a += 3) {
                for (int b = 0; b < dims[v.frame.axisV]; b += 3) {
                    glm::dvec3 voxel(0.0);
                    voxel[v.frame.sliceAxis] = 7;
                    voxel[v.frame.axisU] = a;
                    voxel[v.frame.axisV] = b;
                    const glm::dvec2 p = ui::screenOfVoxel(v, voxel);
                    if (!kRect.contains(p.x, p.y)) {
                        continue;
                    }
                    // The finger lands on the centre of the screen pixel holding the projection.
                    const glm::dvec2 tap = glm::floor(p) + 0.5;
                    const auto found = ui::voxelAtScreen(v, tap);
                    ASSERT_TRUE(found);
                    const glm::dvec2 back = ui::screenOfVoxel(v, *found);
                    EXPECT_LE(std::abs(back.x - p.x), 0.5 + 1e-9);
                    EXPECT_LE(std::abs(back.y - p.y), 0.5 + 1e-9);
                    EXPECT_EQ(glm::ivec3(glm::round(*found)), glm::ivec3(voxel))
                        << "tap " << tap.x << "," << tap.y;
                    ++checked;
                }
            }
            EXPECT_GT(checked, 20);
        }
    }
}

// Independent of the frame's arithmetic: moving the finger right or up moves the tapped point
// in the world toward the side the radiological convention puts there, whatever the scan's
// axis order and flips.
TEST(UiSliceMapping, ScreenDirectionsFollowTheConvention) {
    for (const Case& c : geometries()) {
        for (render::ViewKind kind : kKinds) {
            SCOPED_TRACE(c.name + " " + kindName(kind));
            const ui::SliceView v = viewOf(c.geometry, kind, kRender, kRect);
            glm::dvec3 right;
            glm::dvec3 up;
            screenAxes(kind, right, up);
            const glm::dvec2 centre(kRect.x + 150.0, kRect.y + 120.0);
            const auto at = [&](glm::dvec2 p) {
                return c.geometry.indexToWorld(*ui::voxelAtScreen(v, p));
            };
            const glm::dvec3 toRight = at(centre + glm::dvec2(40, 0)) - at(centre);
            const glm::dvec3 toTop = at(centre - glm::dvec2(0, 40)) - at(centre);
            const double tolerance = c.name == "oblique" ? 0.8 : 0.999;
            EXPECT_GT(glm::dot(glm::normalize(toRight), right), tolerance);
            EXPECT_GT(glm::dot(glm::normalize(toTop), up), tolerance);
        }
    }
}

TEST(UiSliceMapping, ThroughARotatedDisplay) {
    for (int degrees : {90, 180, 270}) {
        const ui::ScreenRotation rotation(degrees, degrees == 180 ? 1280 : 800,
                                          degrees == 180 ? 800 : 1280);
        for (render::ViewKind kind : kKinds) {
            SCOPED_TRACE(std::to_string(degrees) + " " + kindName(kind));
            const Case c = geometries()[1];
            const ui::SliceView v = viewOf(c.geometry, kind, kRender, kRect);
            for (int a = 2; a < c.geometry.dims[v.frame.axisU]; a += 5) {
                glm::dvec3 voxel(0.0);
                voxel[v.frame.sliceAxis] = v.frame.slice;
                voxel[v.frame.axisU] = a;
                voxel[v.frame.axisV] = c.geometry.dims[v.frame.axisV] / 3;
                const glm::dvec2 logical = ui::screenOfVoxel(v, voxel);
                // Where the finger is on the physical panel, at its pixel's centre.
                const glm::dvec2 physical = glm::floor(rotation.toPhysical(logical)) + 0.5;
                platform::InputEvent tap;
                tap.kind = platform::InputEvent::Kind::PointerDown;
                tap.x = static_cast<float>(physical.x);
                tap.y = static_cast<float>(physical.y);
                const platform::InputEvent mapped = rotation.toLogical(tap);
                const auto found = ui::voxelAtScreen(v, glm::dvec2(mapped.x, mapped.y));
                ASSERT_TRUE(found);
                EXPECT_EQ(glm::ivec3(glm::round(*found)), glm::ivec3(voxel));
            }
        }
    }
}

TEST(UiSliceMapping, OutsideTheRectOrScanIsNothing) {
    const Geometry g = baseGeometry();
    const ui::SliceView v = viewOf(g, render::ViewKind::Axial, kRender, kRect);
    EXPECT_FALSE(ui::voxelAtScreen(v, {kRect.x - 1.0, kRect.y + 10.0}));
    EXPECT_FALSE(ui::voxelAtScreen(v, {kRect.x + 10.0, kRect.y + kRect.h + 0.0}));
    EXPECT_FALSE(ui::voxelAtScreen(v, {std::nan(""), kRect.y + 10.0}));
    ui::SliceView empty = v;
    empty.renderSize = {0, 0};
    EXPECT_FALSE(ui::voxelAtScreen(empty, {kRect.x + 10.0, kRect.y + 10.0}));
    EXPECT_TRUE(ui::insideScan({0, 0, 0}, g.dims));
    EXPECT_TRUE(ui::insideScan({39.4, 51.4, 29.4}, g.dims));
    EXPECT_FALSE(ui::insideScan({-0.6, 0, 0}, g.dims));
    EXPECT_FALSE(ui::insideScan({0, 51.6, 0}, g.dims));
    EXPECT_FALSE(ui::insideScan({0, 0, std::nan("")}, g.dims));
}

} // namespace steerseg::test
