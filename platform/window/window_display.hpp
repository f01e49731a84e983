#pragma once

// The window display: a developer's desktop (X11 or Wayland through SDL2) with an OpenGL ES 3.1
// context, vsync where the driver offers it, mouse, keyboard and touch.
#include "platform/display.hpp"

#include <memory>

namespace steerseg::platform {

// Opens a window of options.width x options.height (or fullscreen on the desktop's mode),
// creates its GLES 3.1 context and makes it current. Throws DisplayError naming the step
// ("window: SDL_Init(VIDEO) failed: ...", "window: no OpenGL ES 3.1 context: ...").
std::unique_ptr<Display> openWindowDisplay(const DisplayOptions& options);

} // namespace steerseg::platform
