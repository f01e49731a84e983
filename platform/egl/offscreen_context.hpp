#pragma once

// The offscreen backend: tests, benchmarks, batch commands and headless GPU servers. There is
// no default framebuffer; renderers draw into their own framebuffer objects.
#include "platform/gpu_context.hpp"

#include <memory>
#include <string>

namespace steerseg::platform {

enum class OffscreenPlatform {
    Auto,        // a hardware EGL device if there is one, else Mesa surfaceless
    Surfaceless, // EGL_PLATFORM_SURFACELESS_MESA
    Device,      // EGL_EXT_platform_device (NVIDIA headless and Mesa)
};

// Parses "auto", "surfaceless" or "device"; throws GpuContextError otherwise.
OffscreenPlatform parseOffscreenPlatform(const std::string& name);

// Creates an offscreen GLES 3.1+ context and makes it current. The environment variable
// STEERSEG_EGL_PLATFORM (same words as parseOffscreenPlatform) overrides Auto.
std::unique_ptr<GpuContext>
createOffscreenContext(OffscreenPlatform platform = OffscreenPlatform::Auto);

} // namespace steerseg::platform
