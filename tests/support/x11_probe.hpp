#pragma once

// What the X server shows and a window manager's close request, for the window backend's test.
// Xlib's macros (None, Bool, Status) clash with GoogleTest's, so they stay in x11_probe.cpp.
#include <array>
#include <cstdint>
#include <vector>

namespace steerseg::test {

// The X window SDL made for the current GL context; 0 if there is none or it is not on X11.
unsigned long currentSdlXWindow();

class X11Probe {
  public:
    X11Probe(); // connects to $DISPLAY; connected() says whether it worked
    ~X11Probe();
    X11Probe(const X11Probe&) = delete;
    X11Probe& operator=(const X11Probe&) = delete;

    [[nodiscard]] bool connected() const { return display_ != nullptr; }
    // The default screen's root window: capture(rootWindow(), ...) is a screenshot of the screen.
    [[nodiscard]] unsigned long rootWindow() const;
    // RGB of the pixel the X server shows at (x, y) of `window`; {-1, -1, -1} if unreadable.
    [[nodiscard]] std::array<int, 3> pixel(unsigned long window, int x, int y) const;
    // What the X server shows of `window`'s [0, width) x [0, height): RGBA8 rows top-down, alpha
    // 255, like platform::readFramebuffer; empty if unreadable (unmapped, off screen).
    [[nodiscard]] std::vector<std::uint8_t> capture(unsigned long window, int width,
                                                    int height) const;
    // Sends WM_DELETE_WINDOW, as a window manager does when the close button is clicked.
    bool requestClose(unsigned long window) const;

  private:
    void* display_ = nullptr;
};

} // namespace steerseg::test
