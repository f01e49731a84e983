#pragma once

#include "platform/egl/egl_display.hpp"

#include <EGL/egl.h>

namespace steerseg::platform::egl {

struct ContextConfig {
    EGLint surfaceType = 0;    // 0 for surfaceless use, EGL_WINDOW_BIT for windows/GBM
    EGLint nativeVisualId = 0; // GBM format to match, 0 for any
};

struct Context {
    EGLConfig config = nullptr; // nullptr where EGL_KHR_no_config_context was used
    EGLContext context = EGL_NO_CONTEXT;
};

// Creates an OpenGL ES context of version 3.2, or 3.1 where 3.2 is refused, on `display`.
// Throws GpuContextError naming the failing step.
Context createEsContext(const Display& display, const ContextConfig& config);

// Checks GL_VERSION of the current context and throws "GLES 3.1 context refused: got X" if the
// driver handed back something older than 3.1 (compute shaders are required).
void requireCurrentEs31();

} // namespace steerseg::platform::egl
