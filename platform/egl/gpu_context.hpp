#pragma once

#include <memory>
#include <stdexcept>
#include <string>

namespace steerseg::platform {

// Raised when any step of bringing up EGL/GLES fails; the message names the step.
class GpuContextError : public std::runtime_error {
  public:
    using std::runtime_error::runtime_error;
};

// A current OpenGL ES 3.1+ context. Backends differ in where pixels go (nowhere, a window, a
// KMS plane); the solver and renderer only need the context to be current on their thread.
class GpuContext {
  public:
    virtual ~GpuContext() = default;
    GpuContext() = default;
    GpuContext(const GpuContext&) = delete;
    GpuContext& operator=(const GpuContext&) = delete;

    // "surfaceless", "device", later "gbm" or "window".
    [[nodiscard]] virtual std::string backendName() const = 0;
    virtual void makeCurrent() = 0;
};

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
