#include "platform/egl/offscreen_context.hpp"

#include "platform/egl/egl_context.hpp"

#include <cstdlib>

namespace steerseg::platform {

namespace {

class OffscreenContext final : public GpuContext {
  public:
    OffscreenContext(egl::Display display, egl::Context context)
        : display_(display), context_(context) {}
    ~OffscreenContext() override {
        eglMakeCurrent(display_.display, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
        eglDestroyContext(display_.display, context_.context);
        // No eglTerminate: the EGL display is the process's and the next context reuses it.
        // Terminating it makes Mesa (22.3) dlclose its DRI driver, whose one-time allocations
        // then read as leaks LeakSanitizer cannot name or suppress ("<unknown module>"), failing
        // every GPU test and command under the asan preset.
    }
    OffscreenContext(const OffscreenContext&) = delete;
    OffscreenContext& operator=(const OffscreenContext&) = delete;

    [[nodiscard]] std::string backendName() const override { return display_.platform; }
    [[nodiscard]] bool providesGl() const override { return true; }

    void makeCurrent() override {
        if (eglMakeCurrent(display_.display, EGL_NO_SURFACE, EGL_NO_SURFACE, context_.context) !=
            EGL_TRUE) {
            throw GpuContextError("eglMakeCurrent failed on platform " + display_.platform + " (" +
                                  egl::errorName(eglGetError()) + ")");
        }
    }

  private:
    egl::Display display_;
    egl::Context context_;
};

std::unique_ptr<GpuContext> openOn(const egl::Display& display) {
    egl::Context context;
    try {
        context = egl::createEsContext(display, egl::ContextConfig{});
    } catch (...) {
        eglTerminate(display.display);
        throw;
    }
    auto result = std::make_unique<OffscreenContext>(display, context);
    result->makeCurrent();
    egl::requireCurrentEs31();
    return result;
}

} // namespace

OffscreenPlatform parseOffscreenPlatform(const std::string& name) {
    if (name == "auto") {
        return OffscreenPlatform::Auto;
    }
    if (name == "surfaceless") {
        return OffscreenPlatform::Surfaceless;
    }
    if (name == "device") {
        return OffscreenPlatform::Device;
    }
    throw GpuContextError("unknown EGL platform \"" + name +
                          "\" (expected auto, surfaceless or device)");
}

std::unique_ptr<GpuContext> createOffscreenContext(OffscreenPlatform platform) {
    if (platform == OffscreenPlatform::Auto) {
        if (const char* env = std::getenv("STEERSEG_EGL_PLATFORM")) {
            platform = parseOffscreenPlatform(env);
        }
    }
    switch (platform) {
    case OffscreenPlatform::Surfaceless:
        return openOn(egl::openSurfacelessDisplay());
    case OffscreenPlatform::Device:
        return openOn(egl::openDeviceDisplay());
    case OffscreenPlatform::Auto:
        break;
    }
    // A hardware device first (NVIDIA headless has no surfaceless platform), then Mesa.
    std::string deviceError;
    try {
        return openOn(egl::openDeviceDisplay());
    } catch (const GpuContextError& e) {
        deviceError = e.what();
    }
    try {
        return openOn(egl::openSurfacelessDisplay());
    } catch (const GpuContextError& e) {
        throw GpuContextError(std::string(e.what()) + "; and " + deviceError);
    }
}

} // namespace steerseg::platform
