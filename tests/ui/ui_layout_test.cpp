#include "ui/layout.hpp"
#include "ui/screen_rotation.hpp"

#include <cmath>
#include <gtest/gtest.h>
#include <limits>
#include <stdexcept>

namespace steerseg::test {

using ui::Layout;
using ui::Rect;

namespace {

long area(const Rect& r) {
    return static_cast<long>(r.w) * r.h;
}

bool overlap(const Rect& a, const Rect& b) {
    return a.x < b.x + b.w && b.x < a.x + a.w && a.y < b.y + b.h && b.y < a.y + a.h && !a.empty() &&
           !b.empty();
}

void expectTiles(const Layout& l, int w, int h) {
    const Rect all[] = {l.view3d, l.slice1, l.slice2, l.panel};
    long sum = 0;
    for (const Rect& r : all) {
        EXPECT_GE(r.x, 0);
        EXPECT_GE(r.y, 0);
        EXPECT_GE(r.w, 0);
        EXPECT_GE(r.h, 0);
        EXPECT_LE(r.x + r.w, w);
        EXPECT_LE(r.y + r.h, h);
        sum += area(r);
    }
    for (int i = 0; i < 4; ++i) {
        for (int j = i + 1; j < 4; ++j) {
            EXPECT_FALSE(overlap(all[i], all[j])) << i << " and " << j;
        }
    }
    EXPECT_EQ(sum, static_cast<long>(w) * h) << "the four parts must fill the screen";
}

void expectLandscape(int w, int h, double dpi) {
    SCOPED_TRACE(std::to_string(w) + "x" + std::to_string(h) + " at " + std::to_string(dpi));
    const Layout l = ui::computeLayout(w, h, dpi);
    expectTiles(l, w, h);
    EXPECT_EQ(l.view3d.x, 0);
    EXPECT_EQ(l.view3d.h, h);
    EXPECT_GT(area(l.view3d), area(l.slice1));
    EXPECT_EQ(l.slice1.x, l.view3d.w);
    EXPECT_EQ(l.slice2.x, l.slice1.x);
    EXPECT_EQ(l.slice2.y, l.slice1.y + l.slice1.h);
    EXPECT_EQ(l.panel.x + l.panel.w, w);
    EXPECT_GE(l.panel.w, 5.5 * ui::touchTargetPx(9.0, dpi) - 1.0);
    EXPECT_GT(l.slice1.w, 0);
}

} // namespace

TEST(UiLayout, TouchTargetIsAtLeastNineMillimetres) {
    EXPECT_NEAR(ui::touchTargetPx(9.0, 96.0), 9.0 * 96.0 / 25.4, 1e-9);
    EXPECT_DOUBLE_EQ(ui::touchTargetPx(4.0, 96.0), ui::touchTargetPx(9.0, 96.0));
    EXPECT_NEAR(ui::touchTargetPx(12.0, 254.0), 120.0, 1e-9);
    const double nan = std::numeric_limits<double>::quiet_NaN();
    EXPECT_DOUBLE_EQ(ui::touchTargetPx(9.0, nan), ui::touchTargetPx(9.0, 96.0));
    EXPECT_DOUBLE_EQ(ui::touchTargetPx(9.0, -3.0), ui::touchTargetPx(9.0, 96.0));
    EXPECT_DOUBLE_EQ(ui::touchTargetPx(nan, 96.0), ui::touchTargetPx(9.0, 96.0));
}

TEST(UiLayout, Landscape1280x800) {
    expectLandscape(1280, 800, 96.0);
    expectLandscape(1280, 800, 150.0);
}

TEST(UiLayout, Landscape1920x1080) {
    expectLandscape(1920, 1080, 96.0);
    expectLandscape(1920, 1080, 220.0);
}

TEST(UiLayout, Portrait800x1280StacksViewsAbovePanel) {
    const Layout l = ui::computeLayout(800, 1280, 96.0);
    expectTiles(l, 800, 1280);
    EXPECT_EQ(l.view3d.y, 0);
    EXPECT_EQ(l.view3d.w, 800);
    EXPECT_EQ(l.slice1.y, l.view3d.h);
    EXPECT_EQ(l.slice2.y, l.slice1.y);
    EXPECT_EQ(l.slice2.x, l.slice1.w);
    EXPECT_EQ(l.panel.w, 800);
    EXPECT_EQ(l.panel.y + l.panel.h, 1280);
    EXPECT_GE(l.panel.h, 4.0 * ui::touchTargetPx(9.0, 96.0));
    EXPECT_GT(l.view3d.h, 0);
    EXPECT_GT(l.slice1.h, 0);
}

TEST(UiLayout, TinyAndBadSizesGiveNoNegativeRects) {
    for (const auto& [w, h] :
         {std::pair{1, 1}, {10, 10}, {50, 800}, {800, 50}, {3, 2}, {2, 3}, {136, 40}, {140, 100}}) {
        SCOPED_TRACE(std::to_string(w) + "x" + std::to_string(h));
        expectTiles(ui::computeLayout(w, h, 96.0), w, h);
        expectTiles(ui::computeLayout(w, h, 400.0), w, h);
    }
    for (const auto& [w, h] : {std::pair{0, 0}, {-5, 10}, {10, -5}}) {
        const Layout l = ui::computeLayout(w, h, 96.0);
        EXPECT_TRUE(l.view3d.empty() && l.slice1.empty() && l.slice2.empty() && l.panel.empty());
    }
}

TEST(UiLayout, RegionAtNamesThePartUnderAPoint) {
    const Layout l = ui::computeLayout(1280, 800, 96.0);
    EXPECT_EQ(ui::regionAt(l, 10, 10), ui::Region::View3d);
    EXPECT_EQ(ui::regionAt(l, l.slice1.x + 5, l.slice1.y + 5), ui::Region::Slice1);
    EXPECT_EQ(ui::regionAt(l, l.slice2.x + 5, l.slice2.y + l.slice2.h - 1), ui::Region::Slice2);
    EXPECT_EQ(ui::regionAt(l, 1279, 799), ui::Region::Panel);
    EXPECT_EQ(ui::regionAt(l, 1280, 10), ui::Region::None);
    EXPECT_EQ(ui::regionAt(l, -1, 10), ui::Region::None);
    EXPECT_EQ(ui::regionAt(l, std::nan(""), 10), ui::Region::None);
}

TEST(UiScreenRotation, LogicalSizeAndCorners) {
    const ui::ScreenRotation r0(0, 1280, 800);
    EXPECT_EQ(r0.logicalSize(), glm::ivec2(1280, 800));
    const ui::ScreenRotation r90(90, 800, 1280); // a landscape image on a portrait panel
    EXPECT_EQ(r90.logicalSize(), glm::ivec2(1280, 800));
    // Turned clockwise, the logical top left pixel shows at the physical top right.
    const glm::dvec2 p = r90.toPhysical({0.5, 0.5});
    EXPECT_NEAR(p.x, 799.5, 1e-12);
    EXPECT_NEAR(p.y, 0.5, 1e-12);
    const ui::ScreenRotation r180(180, 1280, 800);
    const glm::dvec2 q = r180.toPhysical({0.5, 0.5});
    EXPECT_NEAR(q.x, 1279.5, 1e-12);
    EXPECT_NEAR(q.y, 799.5, 1e-12);
    const ui::ScreenRotation r270(270, 800, 1280);
    const glm::dvec2 s = r270.toPhysical({0.5, 0.5});
    EXPECT_NEAR(s.x, 0.5, 1e-12);
    EXPECT_NEAR(s.y, 1279.5, 1e-12);
    EXPECT_EQ(ui::ScreenRotation(-90, 800, 1280).degrees(), 270);
    EXPECT_EQ(ui::ScreenRotation(450, 800, 1280).degrees(), 90);
}

TEST(UiScreenRotation, RoundTripsEveryRotation) {
    for (int degrees : {0, 90, 180, 270}) {
        const ui::ScreenRotation r(degrees, 800, 600);
        const glm::ivec2 logical = r.logicalSize();
        for (double x = 0.5; x < logical.x; x += 37.25) {
            for (double y = 0.5; y < logical.y; y += 29.5) {
                const glm::dvec2 phys = r.toPhysical({x, y});
                EXPECT_GE(phys.x, 0.0);
                EXPECT_GE(phys.y, 0.0);
                EXPECT_LE(phys.x, 800.0);
                EXPECT_LE(phys.y, 600.0);
                const glm::dvec2 back = r.toLogical(phys);
                EXPECT_NEAR(back.x, x, 1e-9) << degrees;
                EXPECT_NEAR(back.y, y, 1e-9) << degrees;
            }
        }
    }
}

TEST(UiScreenRotation, MapsPointerEventsOnly) {
    const ui::ScreenRotation r(90, 800, 1280);
    platform::InputEvent down;
    down.kind = platform::InputEvent::Kind::PointerDown;
    down.x = 799.5F;
    down.y = 0.5F;
    const platform::InputEvent mapped = r.toLogical(down);
    EXPECT_NEAR(mapped.x, 0.5F, 1e-4F);
    EXPECT_NEAR(mapped.y, 0.5F, 1e-4F);
    platform::InputEvent key;
    key.kind = platform::InputEvent::Kind::KeyDown;
    key.key = "a";
    key.x = 3.0F;
    EXPECT_EQ(r.toLogical(key).x, 3.0F);
}

TEST(UiScreenRotation, RefusesOddAnglesAndSizes) {
    EXPECT_THROW(ui::ScreenRotation(45, 800, 600), std::invalid_argument);
    EXPECT_THROW(ui::ScreenRotation(0, 0, 600), std::invalid_argument);
    EXPECT_THROW(ui::ScreenRotation(90, 800, -1), std::invalid_argument);
}

} // namespace steerseg::test
