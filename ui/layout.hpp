#pragma once

// Where the kiosk's four parts go on the logical screen, after the paper's Figure 7: the 3D
// view, two slice views (the first with the yellow contour, the second with the speed) and the
// touch panel. Pure arithmetic: the kiosk blits its view textures into these rects and the
// panel is drawn into the last one.
namespace steerseg::ui {

// Logical pixels, origin top left. Never negative in size.
struct Rect {
    int x = 0;
    int y = 0;
    int w = 0;
    int h = 0;
    [[nodiscard]] bool contains(double px, double py) const {
        return px >= x && py >= y && px < x + w && py < y + h;
    }
    [[nodiscard]] bool empty() const { return w <= 0 || h <= 0; }
};

struct Layout {
    Rect view3d;
    Rect slice1; // the scan with the yellow contour
    Rect slice2; // the speed view
    Rect panel;
};

enum class Region { None, View3d, Slice1, Slice2, Panel };

// The smallest comfortable touch target: `mm` (at least 9 mm) at `dpi`, in pixels. A dpi that
// is not a positive finite number counts as 96.
double touchTargetPx(double mm, double dpi);

// Landscape (width >= height): the 3D view large on the left, the two slices stacked in a
// column, the panel on the right, at least 5.5 touch targets wide (a parameter's row). Portrait:
// the 3D view on top, the two slices side by side, the panel below. Sizes <= 0 give empty rects.
// `touchMm`: the touch target (config ui.touch_target_mm, at least 9 mm).
Layout computeLayout(int width, int height, double dpi, double touchMm = 9.0);

Region regionAt(const Layout& layout, double x, double y);

} // namespace steerseg::ui
