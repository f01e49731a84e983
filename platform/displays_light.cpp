// The light build's window and KMS displays: none (SDL2, and libinput's GLib, are not in the GPU
// pack); the offscreen display is the full build's own. Refused with the one line a display
// that cannot open gives (DisplayError: exit status 3).
#include "platform/kms/kms_display.hpp"
#include "platform/window/window_display.hpp"

namespace steerseg::platform {

namespace {

[[noreturn]] void leftOut(const std::string& what, const std::string& library) {
    throw DisplayError(what +
                       " is not in this light build of steerseg (STEERSEG_LIGHT, the GPU "
                       "pack's): it needs " +
                       library + "; use --platform offscreen, or the full build");
}

} // namespace

std::unique_ptr<Display> openWindowDisplay(const DisplayOptions& /*options*/) {
    leftOut("The window display", "SDL2");
}

std::unique_ptr<Display> openKmsDisplay(const DisplayOptions& /*options*/) {
    leftOut("The KMS display", "libinput");
}

} // namespace steerseg::platform
