#pragma once

// The GBM device and scanout surface EGL renders into, and the DRM framebuffers of its buffers.
#include <cstdint>
#include <gbm.h>
#include <string>

namespace steerseg::platform::kms {

class GbmSurface {
  public:
    // An XRGB8888 surface of width x height usable for scanout and rendering on the DRM device
    // `fd`. Throws DisplayError "kms: no GBM device on X" / "kms: no GBM surface of WxH ...".
    GbmSurface(int fd, const std::string& path, int width, int height);
    ~GbmSurface();
    GbmSurface(const GbmSurface&) = delete;
    GbmSurface& operator=(const GbmSurface&) = delete;

    [[nodiscard]] gbm_device* device() const { return device_; }
    [[nodiscard]] gbm_surface* surface() const { return surface_; }
    [[nodiscard]] static std::uint32_t format() { return GBM_FORMAT_XRGB8888; }

    // The buffer EGL just finished (after eglSwapBuffers); nullptr if GBM has none to give.
    gbm_bo* lockFront();
    // Hands a buffer locked with lockFront back to the surface once it is off the screen.
    void release(gbm_bo* bo);
    // The DRM framebuffer of `bo`, created on first use and removed with the buffer. Throws
    // DisplayError "kms: drmModeAddFB2 failed: ..." if the device refuses it.
    std::uint32_t framebufferOf(gbm_bo* bo);

  private:
    int fd_;
    gbm_device* device_ = nullptr;
    gbm_surface* surface_ = nullptr;
};

} // namespace steerseg::platform::kms
