#pragma once

// Which display backend to open when the configuration says "auto" (or nothing): a window where
// a desktop session is running, else offscreen. KMS is never guessed: an appliance names it in
// its configuration, since taking DRM master from a running desktop would blank it.
#include <string>

namespace steerseg::platform {

// The environment variables the choice reads, passed in so that tests control them.
struct DisplayEnvironment {
    std::string waylandDisplay; // $WAYLAND_DISPLAY
    std::string x11Display;     // $DISPLAY
    // Reads them from this process's environment.
    static DisplayEnvironment current();
};

// `configured` if it is "kms", "window" or "offscreen"; for "auto" or "": "window" when
// $WAYLAND_DISPLAY or $DISPLAY is set, else "offscreen". Throws DisplayError for any other word.
std::string defaultPlatform(const std::string& configured, const DisplayEnvironment& environment);

} // namespace steerseg::platform
