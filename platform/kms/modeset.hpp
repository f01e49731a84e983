#pragma once

// Showing framebuffers on one connector: the mode set once, then page flips. Atomic
// modesetting where the device granted DRM_CLIENT_CAP_ATOMIC and a primary plane for the CRTC
// exists, else the legacy drmModeSetCrtc and drmModePageFlip.
#include "platform/kms/drm_device.hpp"

#include <cstdint>
#include <string>
#include <xf86drmMode.h>

namespace steerseg::platform::kms {

class Modeset {
  public:
    // Picks a CRTC for the connector (the one its encoder drives, else the first its encoders
    // can drive) and remembers what that CRTC showed, to restore it on destruction. Throws
    // DisplayError "kms: no CRTC for connector X" and the like.
    Modeset(const DrmDevice& device, const ConnectorInfo& connector, const drmModeModeInfo& mode);
    ~Modeset();
    Modeset(const Modeset&) = delete;
    Modeset& operator=(const Modeset&) = delete;

    // Sets the mode with framebuffer `fb` on it (blocking). Throws DisplayError on refusal.
    void show(std::uint32_t fb);
    // Queues a flip to `fb` at the next vblank; the device then delivers a page-flip event
    // carrying `userData`. Returns the errno of a refusal (EBUSY while a flip is pending), 0 if
    // queued.
    int flip(std::uint32_t fb, void* userData);

    [[nodiscard]] std::uint32_t crtc() const { return crtcId_; }
    [[nodiscard]] bool atomic() const { return atomic_; }

  private:
    struct PlaneProps {
        std::uint32_t fbId = 0, crtcId = 0, srcX = 0, srcY = 0, srcW = 0, srcH = 0, crtcX = 0,
                      crtcY = 0, crtcW = 0, crtcH = 0;
    };
    bool findAtomicObjects();
    int commitAtomic(std::uint32_t fb, std::uint32_t flags, void* userData);

    int fd_;
    std::string connectorName_;
    std::uint32_t connectorId_;
    drmModeModeInfo mode_;
    std::uint32_t crtcId_ = 0;
    int crtcIndex_ = -1;
    drmModeCrtc* saved_ = nullptr;
    bool atomic_ = false;
    // Atomic objects and property ids.
    std::uint32_t planeId_ = 0;
    std::uint32_t modeBlob_ = 0;
    std::uint32_t connectorCrtcProp_ = 0;
    std::uint32_t crtcModeProp_ = 0;
    std::uint32_t crtcActiveProp_ = 0;
    PlaneProps plane_;
};

} // namespace steerseg::platform::kms
