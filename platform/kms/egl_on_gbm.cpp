#include "platform/kms/egl_on_gbm.hpp"

#include "platform/display.hpp"
#include "platform/egl/egl_context.hpp"
#include "platform/egl/egl_display.hpp"
#include "platform/gpu_context.hpp"

#include <EGL/eglext.h>
#include <string>

namespace steerseg::platform::kms {

EglOnGbm::EglOnGbm(const GbmSurface& gbm) {
    const char* client = eglQueryString(EGL_NO_DISPLAY, EGL_EXTENSIONS);
    if (!egl::hasExtension(client, "EGL_KHR_platform_gbm") &&
        !egl::hasExtension(client, "EGL_MESA_platform_gbm")) {
        throw DisplayError("kms: EGL has no GBM platform (EGL_KHR_platform_gbm missing)");
    }
    // eglGetProcAddress returns a generic function pointer by design.
    auto getPlatformDisplay = reinterpret_cast<PFNEGLGETPLATFORMDISPLAYEXTPROC>(
        eglGetProcAddress("eglGetPlatformDisplayEXT"));
    if (getPlatformDisplay == nullptr) {
        throw DisplayError("kms: eglGetPlatformDisplayEXT missing");
    }
    display_ = getPlatformDisplay(EGL_PLATFORM_GBM_KHR, gbm.device(), nullptr);
    if (display_ == EGL_NO_DISPLAY) {
        throw DisplayError("kms: no EGL display on GBM (" + egl::errorName(eglGetError()) + ")");
    }
    EGLint major = 0;
    EGLint minor = 0;
    if (eglInitialize(display_, &major, &minor) != EGL_TRUE) {
        const std::string reason = egl::errorName(eglGetError());
        display_ = EGL_NO_DISPLAY;
        throw DisplayError("kms: eglInitialize on GBM failed (" + reason + ")");
    }
    try {
        const egl::Display display{display_, "gbm"};
        egl::Context context;
        try {
            context = egl::createEsContext(
                display, egl::ContextConfig{EGL_WINDOW_BIT, static_cast<EGLint>(gbm.format())});
        } catch (const GpuContextError& e) {
            throw DisplayError(std::string("kms: ") + e.what() + " (GBM format XRGB8888)");
        }
        context_ = context.context;
        // A window surface on GBM is the gbm_surface itself (EGL_KHR_platform_gbm).
        surface_ =
            eglCreateWindowSurface(display_, context.config,
                                   reinterpret_cast<EGLNativeWindowType>(gbm.surface()), nullptr);
        if (surface_ == EGL_NO_SURFACE) {
            throw DisplayError("kms: no EGL window surface on the GBM surface (" +
                               egl::errorName(eglGetError()) + ")");
        }
        if (eglMakeCurrent(display_, surface_, surface_, context_) != EGL_TRUE) {
            throw DisplayError("kms: eglMakeCurrent on the GBM surface failed (" +
                               egl::errorName(eglGetError()) + ")");
        }
        try {
            egl::requireCurrentEs31();
        } catch (const GpuContextError& e) {
            throw DisplayError(std::string("kms: ") + e.what());
        }
    } catch (...) {
        destroy();
        throw;
    }
}

EglOnGbm::~EglOnGbm() {
    destroy();
}

bool EglOnGbm::swap() {
    return eglSwapBuffers(display_, surface_) == EGL_TRUE;
}

void EglOnGbm::destroy() {
    if (display_ == EGL_NO_DISPLAY) {
        return;
    }
    eglMakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
    if (surface_ != EGL_NO_SURFACE) {
        eglDestroySurface(display_, surface_);
    }
    if (context_ != EGL_NO_CONTEXT) {
        eglDestroyContext(display_, context_);
    }
    eglTerminate(display_);
    display_ = EGL_NO_DISPLAY;
}

} // namespace steerseg::platform::kms
