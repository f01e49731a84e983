#pragma once

// The appliance's display: DRM/KMS through GBM and EGL on the console's monitor, no X server
// (as kmscube). Frames are paced by page flips. pollEvents() delivers the console's touchscreen,
// mouse and keyboard through libinput on seat0 (platform/input/libinput; the calibration from
// DisplayOptions::touchCalibration, else udev's); knobs and the pedal come through the kiosk's
// input hub.
#include "platform/display.hpp"

#include <memory>

namespace steerseg::platform {

// Opens options.drmDevice (else the first card with a connected connector), drives
// options.connector with options.mode (else the first connected connector's preferred mode),
// makes a GLES 3.1 context current on a GBM surface of that size and shows a first, black
// frame. Throws DisplayError with one line naming the failing step ("kms: no DRM device ...",
// "kms: no connector named ...", "kms: no mode ...", "kms: no GBM surface ...",
// "kms: no EGL config ...").
std::unique_ptr<Display> openKmsDisplay(const DisplayOptions& options);

} // namespace steerseg::platform
