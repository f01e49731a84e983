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

// A current OpenGL ES 3.1+ context, or none. Backends are folders beside this file: egl/
// (offscreen: EGL device or Mesa surfaceless), null/ (no GPU at all, for the workflow and UI
// logic), and with the kiosk kms/ and a window backend. They differ in where pixels go
// (nowhere, a window, a KMS plane); the solver and renderer only need the context to be
// current on their thread, and code above platform/ sees only this interface.
class GpuContext {
  public:
    virtual ~GpuContext() = default;
    GpuContext() = default;
    GpuContext(const GpuContext&) = delete;
    GpuContext& operator=(const GpuContext&) = delete;

    // "surfaceless", "device", "null", later "kms" or "window".
    [[nodiscard]] virtual std::string backendName() const = 0;
    // False for the null backend: no GL call may be made.
    [[nodiscard]] virtual bool providesGl() const = 0;
    virtual void makeCurrent() = 0;
};

} // namespace steerseg::platform
