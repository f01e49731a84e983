#include "platform/egl/egl_display.hpp"

#include "platform/egl/offscreen_context.hpp"

#include <EGL/eglext.h>
#include <array>
#include <cstring>
#include <vector>

namespace steerseg::platform::egl {

std::string errorName(EGLint code) {
    switch (code) {
    case EGL_SUCCESS:
        return "EGL_SUCCESS";
    case EGL_NOT_INITIALIZED:
        return "EGL_NOT_INITIALIZED";
    case EGL_BAD_ACCESS:
        return "EGL_BAD_ACCESS";
    case EGL_BAD_ALLOC:
        return "EGL_BAD_ALLOC";
    case EGL_BAD_ATTRIBUTE:
        return "EGL_BAD_ATTRIBUTE";
    case EGL_BAD_CONFIG:
        return "EGL_BAD_CONFIG";
    case EGL_BAD_CONTEXT:
        return "EGL_BAD_CONTEXT";
    case EGL_BAD_CURRENT_SURFACE:
        return "EGL_BAD_CURRENT_SURFACE";
    case EGL_BAD_DISPLAY:
        return "EGL_BAD_DISPLAY";
    case EGL_BAD_MATCH:
        return "EGL_BAD_MATCH";
    case EGL_BAD_NATIVE_PIXMAP:
        return "EGL_BAD_NATIVE_PIXMAP";
    case EGL_BAD_NATIVE_WINDOW:
        return "EGL_BAD_NATIVE_WINDOW";
    case EGL_BAD_PARAMETER:
        return "EGL_BAD_PARAMETER";
    case EGL_BAD_SURFACE:
        return "EGL_BAD_SURFACE";
    case EGL_CONTEXT_LOST:
        return "EGL_CONTEXT_LOST";
    default:
        return "EGL error " + std::to_string(code);
    }
}

bool hasExtension(const char* list, const std::string& name) {
    if (list == nullptr) {
        return false;
    }
    const std::string all = std::string(" ") + list + " ";
    return all.find(" " + name + " ") != std::string::npos;
}

namespace {

template <typename Fn> Fn loadProc(const char* name) {
    // eglGetProcAddress returns a generic function pointer by design.
    return reinterpret_cast<Fn>(eglGetProcAddress(name));
}

void requireClientExtension(const char* ext, const std::string& platform) {
    const char* client = eglQueryString(EGL_NO_DISPLAY, EGL_EXTENSIONS);
    if (!hasExtension(client, ext)) {
        throw GpuContextError("no EGL display on platform " + platform + ": client extension " +
                              ext + " missing");
    }
}

Display initialise(EGLDisplay display, const std::string& platform) {
    if (display == EGL_NO_DISPLAY) {
        throw GpuContextError("no EGL display on platform " + platform + " (" +
                              errorName(eglGetError()) + ")");
    }
    EGLint major = 0;
    EGLint minor = 0;
    if (eglInitialize(display, &major, &minor) != EGL_TRUE) {
        throw GpuContextError("eglInitialize failed on platform " + platform + " (" +
                              errorName(eglGetError()) + ")");
    }
    return Display{display, platform};
}

} // namespace

Display openSurfacelessDisplay() {
    requireClientExtension("EGL_MESA_platform_surfaceless", "surfaceless");
    auto getPlatformDisplay = loadProc<PFNEGLGETPLATFORMDISPLAYEXTPROC>("eglGetPlatformDisplayEXT");
    if (getPlatformDisplay == nullptr) {
        throw GpuContextError(
            "no EGL display on platform surfaceless: eglGetPlatformDisplayEXT missing");
    }
    return initialise(
        getPlatformDisplay(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr),
        "surfaceless");
}

Display openDeviceDisplay() {
    requireClientExtension("EGL_EXT_device_enumeration", "device");
    requireClientExtension("EGL_EXT_platform_device", "device");
    auto queryDevices = loadProc<PFNEGLQUERYDEVICESEXTPROC>("eglQueryDevicesEXT");
    auto queryDeviceString = loadProc<PFNEGLQUERYDEVICESTRINGEXTPROC>("eglQueryDeviceStringEXT");
    auto getPlatformDisplay = loadProc<PFNEGLGETPLATFORMDISPLAYEXTPROC>("eglGetPlatformDisplayEXT");
    if (queryDevices == nullptr || queryDeviceString == nullptr || getPlatformDisplay == nullptr) {
        throw GpuContextError("no EGL display on platform device: device entry points missing");
    }
    std::array<EGLDeviceEXT, 16> devices{};
    EGLint count = 0;
    if (queryDevices(static_cast<EGLint>(devices.size()), devices.data(), &count) != EGL_TRUE ||
        count <= 0) {
        throw GpuContextError("no EGL display on platform device: no EGL devices found");
    }
    // Mesa lists its software rasteriser as a device too; a real GPU wins over it.
    std::vector<EGLDeviceEXT> ordered;
    for (EGLint i = 0; i < count; ++i) {
        if (!hasExtension(queryDeviceString(devices[i], EGL_EXTENSIONS),
                          "EGL_MESA_device_software")) {
            ordered.push_back(devices[i]);
        }
    }
    for (EGLint i = 0; i < count; ++i) {
        if (hasExtension(queryDeviceString(devices[i], EGL_EXTENSIONS),
                         "EGL_MESA_device_software")) {
            ordered.push_back(devices[i]);
        }
    }
    std::string lastError = "no usable device";
    for (EGLDeviceEXT device : ordered) {
        EGLDisplay display = getPlatformDisplay(EGL_PLATFORM_DEVICE_EXT, device, nullptr);
        if (display == EGL_NO_DISPLAY) {
            lastError = errorName(eglGetError());
            continue;
        }
        EGLint major = 0;
        EGLint minor = 0;
        if (eglInitialize(display, &major, &minor) == EGL_TRUE) {
            return Display{display, "device"};
        }
        lastError = errorName(eglGetError());
    }
    throw GpuContextError("no EGL display on platform device: " + lastError);
}

} // namespace steerseg::platform::egl
