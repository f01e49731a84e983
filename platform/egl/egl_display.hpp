#pragma once

#include <EGL/egl.h>
#include <string>

namespace steerseg::platform::egl {

// Names an EGL error code ("EGL_BAD_MATCH") for messages.
std::string errorName(EGLint code);

// True if the space-separated extension list contains `name` as a whole word.
bool hasExtension(const char* list, const std::string& name);

struct Display {
    EGLDisplay display = EGL_NO_DISPLAY;
    std::string platform; // "surfaceless" or "device"
};

// Opens and initialises an EGL display on Mesa's surfaceless platform.
Display openSurfacelessDisplay();

// Opens and initialises an EGL display on an EGL device, preferring hardware over Mesa's
// software device.
Display openDeviceDisplay();

} // namespace steerseg::platform::egl
