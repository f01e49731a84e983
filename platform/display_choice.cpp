#include "platform/display_choice.hpp"

#include "platform/display.hpp"

#include <cstdlib>

namespace steerseg::platform {

DisplayEnvironment DisplayEnvironment::current() {
    DisplayEnvironment environment;
    if (const char* wayland = std::getenv("WAYLAND_DISPLAY")) {
        environment.waylandDisplay = wayland;
    }
    if (const char* x11 = std::getenv("DISPLAY")) {
        environment.x11Display = x11;
    }
    return environment;
}

std::string defaultPlatform(const std::string& configured, const DisplayEnvironment& environment) {
    if (configured == "kms" || configured == "window" || configured == "offscreen") {
        return configured;
    }
    if (!configured.empty() && configured != "auto") {
        throw DisplayError("unknown display platform \"" + configured +
                           "\" (expected kms, window, offscreen or auto)");
    }
    if (!environment.waylandDisplay.empty() || !environment.x11Display.empty()) {
        return "window";
    }
    return "offscreen";
}

} // namespace steerseg::platform
