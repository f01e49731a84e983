#include "support/x11_probe.hpp"

#include <SDL.h>
#include <SDL_syswm.h>
#include <X11/Xlib.h>
#include <X11/Xutil.h>
#include <chrono>
#include <thread>

namespace steerseg::test {

namespace {

::Display* xdisplay(void* handle) {
    return static_cast<::Display*>(handle);
}

int channel(unsigned long pixel, unsigned long mask) {
    int shift = 0;
    while (mask != 0 && (mask & 1UL) == 0) {
        mask >>= 1U;
        ++shift;
    }
    return static_cast<int>((pixel >> static_cast<unsigned>(shift)) & mask);
}

} // namespace

unsigned long currentSdlXWindow() {
    SDL_Window* window = SDL_GL_GetCurrentWindow();
    if (window == nullptr) {
        return 0;
    }
    SDL_SysWMinfo wm;
    SDL_VERSION(&wm.version);
    if (SDL_GetWindowWMInfo(window, &wm) != SDL_TRUE || wm.subsystem != SDL_SYSWM_X11) {
        return 0;
    }
    return wm.info.x11.window;
}

X11Probe::X11Probe() {
    // An X server resets when its last client leaves and refuses connections meanwhile;
    // xvfb-run -s -noreset avoids that, and a few tries cover a server started without it.
    for (int attempt = 0; attempt < 20 && display_ == nullptr; ++attempt) {
        display_ = XOpenDisplay(nullptr);
        if (display_ == nullptr) {
            std::this_thread::sleep_for(std::chrono::milliseconds(50));
        }
    }
}

X11Probe::~X11Probe() {
    if (display_ != nullptr) {
        XCloseDisplay(xdisplay(display_));
    }
}

unsigned long X11Probe::rootWindow() const {
    return display_ == nullptr ? 0UL : XDefaultRootWindow(xdisplay(display_));
}

std::array<int, 3> X11Probe::pixel(unsigned long window, int x, int y) const {
    XImage* image = XGetImage(xdisplay(display_), window, x, y, 1, 1, AllPlanes, ZPixmap);
    if (image == nullptr) {
        return {-1, -1, -1};
    }
    const unsigned long value = XGetPixel(image, 0, 0);
    const std::array<int, 3> rgb{channel(value, image->red_mask), channel(value, image->green_mask),
                                 channel(value, image->blue_mask)};
    XDestroyImage(image);
    return rgb;
}

std::vector<std::uint8_t> X11Probe::capture(unsigned long window, int width, int height) const {
    XImage* image = XGetImage(xdisplay(display_), window, 0, 0, static_cast<unsigned>(width),
                              static_cast<unsigned>(height), AllPlanes, ZPixmap);
    if (image == nullptr) {
        return {};
    }
    std::vector<std::uint8_t> rgba(static_cast<std::size_t>(width) * height * 4);
    std::size_t at = 0;
    for (int y = 0; y < height; ++y) {
        for (int x = 0; x < width; ++x) {
            const unsigned long value = XGetPixel(image, x, y);
            rgba[at++] = static_cast<std::uint8_t>(channel(value, image->red_mask));
            rgba[at++] = static_cast<std::uint8_t>(channel(value, image->green_mask));
            rgba[at++] = static_cast<std::uint8_t>(channel(value, image->blue_mask));
            rgba[at++] = 255;
        }
    }
    XDestroyImage(image);
    return rgba;
}

bool X11Probe::requestClose(unsigned long window) const {
    ::Display* x = xdisplay(display_);
    XEvent close{};
    close.xclient.type = ClientMessage;
    close.xclient.window = window;
    close.xclient.message_type = XInternAtom(x, "WM_PROTOCOLS", False);
    close.xclient.format = 32;
    close.xclient.data.l[0] = static_cast<long>(XInternAtom(x, "WM_DELETE_WINDOW", False));
    close.xclient.data.l[1] = CurrentTime;
    const bool sent = XSendEvent(x, window, False, NoEventMask, &close) != 0;
    XFlush(x);
    return sent;
}

} // namespace steerseg::test
