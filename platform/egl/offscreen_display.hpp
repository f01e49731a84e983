#pragma once

// The offscreen display: tests, CI and the headless demo. A virtual screen of the size in
// DisplayOptions, drawn into a framebuffer object on the offscreen EGL context; scripts inject
// the input, so pollEvents() delivers nothing. platform/gl_readback.hpp reads its frames.
#include "platform/display.hpp"
#include "platform/egl/offscreen_context.hpp"

#include <memory>

namespace steerseg::platform {

// Creates the offscreen context (see createOffscreenContext), makes it current and attaches an
// RGBA8 colour and a depth-stencil renderbuffer of options.width x options.height to a
// framebuffer object. Throws DisplayError naming the step ("offscreen: ...").
std::unique_ptr<Display> openOffscreenDisplay(const DisplayOptions& options,
                                              OffscreenPlatform platform = OffscreenPlatform::Auto);

} // namespace steerseg::platform
