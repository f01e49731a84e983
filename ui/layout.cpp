#include "ui/layout.hpp"

#include <algorithm>
#include <cmath>

namespace steerseg::ui {

namespace {

constexpr double kMinTouchMm = 9.0;
constexpr double kFallbackDpi = 96.0;

int px(double value) {
    return std::max(0, static_cast<int>(std::lround(value)));
}

} // namespace

double touchTargetPx(double mm, double dpi) {
    if (!(dpi > 0.0) || !std::isfinite(dpi)) {
        dpi = kFallbackDpi;
    }
    const double size = std::isfinite(mm) ? std::max(mm, kMinTouchMm) : kMinTouchMm;
    return size * dpi / 25.4;
}

Layout computeLayout(int width, int height, double dpi, double touchMm) {
    Layout l;
    if (width <= 0 || height <= 0) {
        return l;
    }
    const double touch = touchTargetPx(touchMm, dpi);
    if (width >= height) {
        // The panel's widest row is a name, -, a slider and +: four targets, their gaps and
        // the window's padding.
        const int panelW = std::min(width, std::max(px(5.5 * touch), px(0.26 * width)));
        const int viewsW = width - panelW;
        // Slices as near square as the column allows (half the height), the 3D view the rest.
        const int sliceW = std::min(height / 2, px(0.4 * viewsW));
        const int view3dW = viewsW - sliceW;
        const int topH = height / 2;
        l.view3d = {0, 0, view3dW, height};
        l.slice1 = {view3dW, 0, sliceW, topH};
        l.slice2 = {view3dW, topH, sliceW, height - topH};
        l.panel = {viewsW, 0, panelW, height};
    } else {
        const int panelH = std::min(height, std::max(px(6.0 * touch), px(0.36 * height)));
        const int viewsH = height - panelH;
        const int sliceH = std::min(width / 2, px(0.45 * viewsH));
        const int view3dH = viewsH - sliceH;
        const int leftW = width / 2;
        l.view3d = {0, 0, width, view3dH};
        l.slice1 = {0, view3dH, leftW, sliceH};
        l.slice2 = {leftW, view3dH, width - leftW, sliceH};
        l.panel = {0, viewsH, width, panelH};
    }
    return l;
}

Region regionAt(const Layout& layout, double x, double y) {
    if (layout.panel.contains(x, y)) {
        return Region::Panel;
    }
    if (layout.slice1.contains(x, y)) {
        return Region::Slice1;
    }
    if (layout.slice2.contains(x, y)) {
        return Region::Slice2;
    }
    if (layout.view3d.contains(x, y)) {
        return Region::View3d;
    }
    return Region::None;
}

} // namespace steerseg::ui
