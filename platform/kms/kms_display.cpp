#include "platform/kms/kms_display.hpp"

#include "platform/input/libinput/touch_input.hpp"
#include "platform/kms/drm_device.hpp"
#include "platform/kms/egl_on_gbm.hpp"
#include "platform/kms/gbm_surface.hpp"
#include "platform/kms/modeset.hpp"
#include "platform/kms/output_selection.hpp"

#include <GLES3/gl31.h>
#include <cerrno>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <poll.h>
#include <xf86drm.h>

namespace steerseg::platform {

namespace {

// A flip normally lands within one refresh (17 ms at 60 Hz); past this something is wrong (a
// hung driver, a monitor switched off) and the loop goes on rather than waits.
constexpr int kFlipTimeoutMs = 100;

// The console's touchscreen, mouse and keyboard come with the display (libinput on seat0, as
// a compositor would take them), so the kiosk reads input the same way on every backend. A
// console without them (knobs only) or without permission still shows its picture: the
// reason is logged once and pollEvents() delivers nothing.
std::unique_ptr<input::TouchInput> openConsoleInput(const DisplayOptions& options, int width,
                                                    int height) {
    input::TouchInputOptions o;
    o.screenWidth = width;
    o.screenHeight = height;
    if (!options.touchCalibration.empty()) {
        std::string problem;
        o.calibration = input::parseCalibrationMatrix(options.touchCalibration, problem);
        if (!o.calibration) {
            std::fprintf(stderr, "kms: touch calibration \"%s\" ignored: %s\n",
                         options.touchCalibration.c_str(), problem.c_str());
        }
    }
    std::string problem;
    auto touch = input::TouchInput::open(o, problem);
    if (!touch) {
        std::fprintf(stderr, "kms: no touch, mouse or keyboard input: %s\n", problem.c_str());
    }
    return touch;
}

class KmsDisplay final : public Display {
  public:
    explicit KmsDisplay(const DisplayOptions& options) {
        device_ = kms::openDrmDevice(options.drmDevice);
        const kms::DrmConnectors found = kms::readConnectors(device_->fd(), device_->path());
        const kms::OutputChoice choice = kms::selectOutput(found.connectors, options);
        const kms::ConnectorInfo& connector = found.connectors[choice.connector];
        const kms::ModeInfo& mode = connector.modes[choice.mode];
        const drmModeModeInfo& drmMode = found.modes[choice.connector][choice.mode];

        gbm_ = std::make_unique<kms::GbmSurface>(device_->fd(), device_->path(), mode.width,
                                                 mode.height);
        egl_ = std::make_unique<kms::EglOnGbm>(*gbm_);
        modeset_ = std::make_unique<kms::Modeset>(*device_, connector, drmMode);

        // The first frame is black, so the mode is set on a defined picture.
        glClearColor(0.0F, 0.0F, 0.0F, 1.0F);
        glClear(GL_COLOR_BUFFER_BIT);
        if (!egl_->swap()) {
            throw DisplayError("kms: eglSwapBuffers of the first frame failed");
        }
        front_ = gbm_->lockFront();
        if (front_ == nullptr) {
            throw DisplayError("kms: the GBM surface gave no buffer for the first frame");
        }
        modeset_->show(gbm_->framebufferOf(front_));

        info_.width = mode.width;
        info_.height = mode.height;
        info_.refreshHz = mode.refreshHz;
        info_.dpi = kms::dpiOf(mode, connector.mmWidth).value_or(96.0);
        char dpi[32];
        std::snprintf(dpi, sizeof dpi, "%.0f", info_.dpi);
        info_.description = "kms " + device_->path() + " (" + device_->driver() + ") " +
                            connector.name + " " + std::to_string(mode.width) + "x" +
                            std::to_string(mode.height) + "@" + std::to_string(mode.refreshHz) +
                            ", " + dpi + " dpi, " + (modeset_->atomic() ? "atomic" : "legacy") +
                            " modesetting";
        input_ = openConsoleInput(options, mode.width, mode.height);
    }

    ~KmsDisplay() override {
        // A flip still queued would land on a buffer about to be freed.
        if (pending_ != nullptr) {
            waitForFlip(kFlipTimeoutMs);
        }
        modeset_.reset(); // restores the console's CRTC before our buffers go
        if (gbm_) {
            gbm_->release(pending_);
            gbm_->release(front_);
        }
        egl_.reset();
        gbm_.reset();
    }
    KmsDisplay(const KmsDisplay&) = delete;
    KmsDisplay& operator=(const KmsDisplay&) = delete;

    [[nodiscard]] const DisplayInfo& info() const override { return info_; }
    [[nodiscard]] unsigned int framebuffer() const override { return 0; }

    void present() override {
        if (pending_ != nullptr) {
            waitForFlip(0); // the last frame's flip timed out: take its event if it came since
        }
        if (!egl_->swap()) {
            std::fprintf(stderr, "kms: eglSwapBuffers failed (EGL error 0x%x); frame dropped\n",
                         static_cast<unsigned>(eglGetError()));
            return;
        }
        gbm_bo* next = gbm_->lockFront();
        if (next == nullptr) {
            std::fprintf(stderr, "kms: the GBM surface gave no buffer; frame dropped\n");
            return;
        }
        if (pending_ != nullptr) {
            // The screen still waits for an earlier frame: drop this one rather than block.
            gbm_->release(next);
            return;
        }
        int error = 0;
        try {
            error = modeset_->flip(gbm_->framebufferOf(next), this);
        } catch (const DisplayError& e) {
            std::fprintf(stderr, "%s; frame dropped\n", e.what());
            gbm_->release(next);
            return;
        }
        if (error != 0) {
            std::fprintf(stderr, "kms: page flip on CRTC %u refused: %s; frame dropped\n",
                         modeset_->crtc(), std::strerror(error));
            gbm_->release(next);
            return;
        }
        pending_ = next;
        waitForFlip(kFlipTimeoutMs);
    }

    void pollEvents(std::vector<InputEvent>& out) override {
        if (!input_) {
            return;
        }
        const double now =
            std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch())
                .count();
        input_->poll(now, out);
        for (const std::string& problem : input_->takeProblems()) {
            std::fprintf(stderr, "kms: %s\n", problem.c_str());
        }
    }

  private:
    static void onFlip(int /*fd*/, unsigned int /*frame*/, unsigned int /*sec*/,
                       unsigned int /*usec*/, void* data) {
        static_cast<KmsDisplay*>(data)->flipped();
    }

    void flipped() {
        gbm_->release(front_);
        front_ = pending_;
        pending_ = nullptr;
    }

    // Handles DRM events until the pending flip lands or `timeoutMs` passes (0: only what has
    // arrived); logs the first timeout of a stall.
    void waitForFlip(int timeoutMs) {
        drmEventContext events{};
        events.version = 2;
        events.page_flip_handler = &KmsDisplay::onFlip;
        const auto deadline =
            std::chrono::steady_clock::now() + std::chrono::milliseconds(timeoutMs);
        while (pending_ != nullptr) {
            const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(
                                  deadline - std::chrono::steady_clock::now())
                                  .count();
            pollfd fd{device_->fd(), POLLIN, 0};
            const int ready = ::poll(&fd, 1, left > 0 ? static_cast<int>(left) : 0);
            if (ready < 0 && errno == EINTR) {
                continue;
            }
            if (ready <= 0) {
                if (timeoutMs > 0 && !stallLogged_) {
                    std::fprintf(stderr,
                                 "kms: page flip on CRTC %u not done after %d ms; dropping frames "
                                 "until it is\n",
                                 modeset_->crtc(), timeoutMs);
                    stallLogged_ = true;
                }
                return;
            }
            drmHandleEvent(device_->fd(), &events);
        }
        stallLogged_ = false;
    }

    std::unique_ptr<kms::DrmDevice> device_;
    std::unique_ptr<kms::GbmSurface> gbm_;
    std::unique_ptr<kms::EglOnGbm> egl_;
    std::unique_ptr<kms::Modeset> modeset_;
    std::unique_ptr<input::TouchInput> input_;
    gbm_bo* front_ = nullptr;   // on the screen
    gbm_bo* pending_ = nullptr; // queued to flip
    bool stallLogged_ = false;
    DisplayInfo info_;
};

} // namespace

std::unique_ptr<Display> openKmsDisplay(const DisplayOptions& options) {
    return std::make_unique<KmsDisplay>(options);
}

} // namespace steerseg::platform
