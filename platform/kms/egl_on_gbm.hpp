#pragma once

// EGL on the GBM platform: the display, a GLES 3.1 context whose config matches the GBM
// surface's format, and the window surface over that GBM surface.
#include "platform/kms/gbm_surface.hpp"

#include <EGL/egl.h>

namespace steerseg::platform::kms {

class EglOnGbm {
  public:
    // Creates all three and makes the context current. Throws DisplayError "kms: ..." naming
    // the step (no GBM platform, no EGL config for XRGB8888, context refused, no surface).
    explicit EglOnGbm(const GbmSurface& gbm);
    ~EglOnGbm();
    EglOnGbm(const EglOnGbm&) = delete;
    EglOnGbm& operator=(const EglOnGbm&) = delete;

    // eglSwapBuffers; false (with eglGetError pending) if EGL refused.
    bool swap();

  private:
    void destroy();

    EGLDisplay display_ = EGL_NO_DISPLAY;
    EGLContext context_ = EGL_NO_CONTEXT;
    EGLSurface surface_ = EGL_NO_SURFACE;
};

} // namespace steerseg::platform::kms
