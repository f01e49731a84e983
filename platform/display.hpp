#pragma once

// A screen to draw the kiosk's frames on and the pointer and key events that come with it:
// DRM/KMS on the appliance (kms/), a desktop window (window/), or an offscreen framebuffer in
// tests (egl/offscreen_display). Each backend's factory header names its open function; every
// failing step of opening throws DisplayError with one line naming the step.
#include "platform/input_event.hpp"

#include <stdexcept>
#include <string>
#include <vector>

namespace steerseg::platform {

class DisplayError : public std::runtime_error {
  public:
    using std::runtime_error::runtime_error;
};

struct DisplayOptions {
    int width = 1280; // offscreen: the virtual screen; window: the initial size
    int height = 800;
    bool fullscreen = false; // window backend
    std::string drmDevice;   // kms: "" = the first card with a connected connector
    std::string connector;   // kms: "HDMI-A-1", "" = the first connected one
    std::string mode;        // kms: "1920x1080" or "1920x1080@60", "" = the preferred mode
    // kms: the touchscreen's libinput calibration, "a b c d e f"; "" = udev's.
    std::string touchCalibration;
    std::string title = "steerseg";
};

struct DisplayInfo {
    int width = 0; // the framebuffer's size in pixels
    int height = 0;
    double dpi = 96.0;       // from the connector's physical size where it is known
    double refreshHz = 0.0;  // 0: not paced (offscreen)
    std::string description; // one line for the log: backend, device, mode
};

// Owns a current GLES 3.1 context for its whole life (one thread).
class Display {
  public:
    virtual ~Display() = default;
    [[nodiscard]] virtual const DisplayInfo& info() const = 0;
    // The framebuffer a frame is drawn into (0 for a window or a KMS surface).
    [[nodiscard]] virtual unsigned int framebuffer() const = 0;
    // Shows the frame just drawn. Window and KMS wait for the flip (vsync paces the loop);
    // offscreen returns at once.
    virtual void present() = 0;
    // Appends the events that arrived since the last call; never blocks. Positions are in the
    // framebuffer's pixels. A closed window or a lost display gives a Quit event.
    virtual void pollEvents(std::vector<InputEvent>& out) = 0;
};

} // namespace steerseg::platform
