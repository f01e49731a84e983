#include "platform/egl/egl_context.hpp"

#include "platform/egl/offscreen_context.hpp"

#include <EGL/eglext.h>
#include <GLES3/gl31.h>
#include <array>
#include <cstdio>
#include <vector>

namespace steerseg::platform::egl {

namespace {

EGLConfig chooseConfig(const Display& display, const ContextConfig& config) {
    const EGLint attribs[] = {EGL_RENDERABLE_TYPE,
                              EGL_OPENGL_ES3_BIT,
                              EGL_SURFACE_TYPE,
                              config.surfaceType,
                              EGL_RED_SIZE,
                              8,
                              EGL_GREEN_SIZE,
                              8,
                              EGL_BLUE_SIZE,
                              8,
                              EGL_NONE};
    EGLint count = 0;
    if (eglChooseConfig(display.display, attribs, nullptr, 0, &count) != EGL_TRUE || count <= 0) {
        throw GpuContextError("no EGL config with OpenGL ES 3 on platform " + display.platform +
                              " (" + errorName(eglGetError()) + ")");
    }
    std::vector<EGLConfig> configs(static_cast<std::size_t>(count));
    eglChooseConfig(display.display, attribs, configs.data(), count, &count);
    if (config.nativeVisualId == 0) {
        return configs.front();
    }
    for (EGLConfig c : configs) {
        EGLint id = 0;
        if (eglGetConfigAttrib(display.display, c, EGL_NATIVE_VISUAL_ID, &id) == EGL_TRUE &&
            id == config.nativeVisualId) {
            return c;
        }
    }
    throw GpuContextError("no EGL config matches native visual " +
                          std::to_string(config.nativeVisualId) + " on platform " +
                          display.platform);
}

} // namespace

Context createEsContext(const Display& display, const ContextConfig& config) {
    if (eglBindAPI(EGL_OPENGL_ES_API) != EGL_TRUE) {
        throw GpuContextError("eglBindAPI(OpenGL ES) failed on platform " + display.platform);
    }
    const char* ext = eglQueryString(display.display, EGL_EXTENSIONS);
    Context result;
    if (config.surfaceType == 0 && hasExtension(ext, "EGL_KHR_no_config_context")) {
        result.config = nullptr; // EGL_NO_CONFIG_KHR
    } else {
        result.config = chooseConfig(display, config);
    }
    if (config.surfaceType == 0 && !hasExtension(ext, "EGL_KHR_surfaceless_context")) {
        throw GpuContextError("EGL_KHR_surfaceless_context missing on platform " +
                              display.platform);
    }
    EGLint lastError = EGL_SUCCESS;
    for (EGLint minor : {2, 1}) {
        const EGLint attribs[] = {EGL_CONTEXT_MAJOR_VERSION, 3, EGL_CONTEXT_MINOR_VERSION, minor,
                                  EGL_NONE};
        result.context = eglCreateContext(display.display, result.config, EGL_NO_CONTEXT, attribs);
        if (result.context != EGL_NO_CONTEXT) {
            return result;
        }
        lastError = eglGetError();
    }
    throw GpuContextError("GLES 3.1 context refused on platform " + display.platform + " (" +
                          errorName(lastError) + ")");
}

void requireCurrentEs31() {
    const auto* version = reinterpret_cast<const char*>(glGetString(GL_VERSION));
    if (version == nullptr) {
        throw GpuContextError("GLES 3.1 context refused: glGetString(GL_VERSION) returned nothing");
    }
    int major = 0;
    int minor = 0;
    if (std::sscanf(version, "OpenGL ES %d.%d", &major, &minor) != 2) {
        throw GpuContextError(std::string("GLES 3.1 context refused: unrecognised version \"") +
                              version + "\"");
    }
    if (major < 3 || (major == 3 && minor < 1)) {
        throw GpuContextError("GLES 3.1 context refused: got " + std::to_string(major) + "." +
                              std::to_string(minor));
    }
}

} // namespace steerseg::platform::egl
