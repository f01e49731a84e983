#include "platform/egl/offscreen_display.hpp"

#include <GLES3/gl31.h>
#include <string>

namespace steerseg::platform {

namespace {

// The largest virtual screen accepted: 8K, far above any console panel; a bigger request is a
// typo that would otherwise end in an allocation failure deep in the driver.
constexpr int kMaxSide = 8192;

class OffscreenDisplay final : public Display {
  public:
    OffscreenDisplay(std::unique_ptr<GpuContext> context, int width, int height)
        : context_(std::move(context)) {
        glGenFramebuffers(1, &framebuffer_);
        glGenRenderbuffers(2, renderbuffers_);
        glBindRenderbuffer(GL_RENDERBUFFER, renderbuffers_[0]);
        glRenderbufferStorage(GL_RENDERBUFFER, GL_RGBA8, width, height);
        glBindRenderbuffer(GL_RENDERBUFFER, renderbuffers_[1]);
        glRenderbufferStorage(GL_RENDERBUFFER, GL_DEPTH24_STENCIL8, width, height);
        glBindRenderbuffer(GL_RENDERBUFFER, 0);
        glBindFramebuffer(GL_FRAMEBUFFER, framebuffer_);
        glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER,
                                  renderbuffers_[0]);
        glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_STENCIL_ATTACHMENT, GL_RENDERBUFFER,
                                  renderbuffers_[1]);
        const GLenum status = glCheckFramebufferStatus(GL_FRAMEBUFFER);
        const GLenum error = glGetError();
        glBindFramebuffer(GL_FRAMEBUFFER, 0);
        if (status != GL_FRAMEBUFFER_COMPLETE || error != GL_NO_ERROR) {
            release();
            throw DisplayError("offscreen: framebuffer of " + std::to_string(width) + "x" +
                               std::to_string(height) + " incomplete (status " +
                               std::to_string(status) + ", GL error " + std::to_string(error) +
                               ")");
        }
        info_.width = width;
        info_.height = height;
        info_.dpi = 96.0;
        info_.refreshHz = 0.0;
        info_.description = "offscreen " + std::to_string(width) + "x" + std::to_string(height) +
                            " (EGL " + context_->backendName() + ")";
    }
    ~OffscreenDisplay() override { release(); }
    OffscreenDisplay(const OffscreenDisplay&) = delete;
    OffscreenDisplay& operator=(const OffscreenDisplay&) = delete;

    [[nodiscard]] const DisplayInfo& info() const override { return info_; }
    [[nodiscard]] unsigned int framebuffer() const override { return framebuffer_; }
    // Nothing is shown; the flush only hands the frame to the driver so a later readback or
    // the next frame does not wait for all of it at once.
    void present() override { glFlush(); }
    void pollEvents(std::vector<InputEvent>& /*out*/) override {}

  private:
    void release() {
        glDeleteFramebuffers(1, &framebuffer_);
        glDeleteRenderbuffers(2, renderbuffers_);
        framebuffer_ = 0;
        renderbuffers_[0] = renderbuffers_[1] = 0;
    }

    std::unique_ptr<GpuContext> context_;
    GLuint framebuffer_ = 0;
    GLuint renderbuffers_[2] = {0, 0};
    DisplayInfo info_;
};

} // namespace

std::unique_ptr<Display> openOffscreenDisplay(const DisplayOptions& options,
                                              OffscreenPlatform platform) {
    if (options.width <= 0 || options.height <= 0 || options.width > kMaxSide ||
        options.height > kMaxSide) {
        throw DisplayError("offscreen: bad screen size " + std::to_string(options.width) + "x" +
                           std::to_string(options.height) + " (1.." + std::to_string(kMaxSide) +
                           " each)");
    }
    std::unique_ptr<GpuContext> context;
    try {
        context = createOffscreenContext(platform);
    } catch (const GpuContextError& e) {
        throw DisplayError(std::string("offscreen: ") + e.what());
    }
    return std::make_unique<OffscreenDisplay>(std::move(context), options.width, options.height);
}

} // namespace steerseg::platform
