#pragma once

// The DRM device the KMS display drives: opened, made DRM master, its client capabilities set,
// and its connectors read into output_selection's plain structs.
#include "platform/kms/output_selection.hpp"

#include <cstdint>
#include <memory>
#include <string>
#include <vector>
#include <xf86drmMode.h>

namespace steerseg::platform::kms {

class DrmDevice {
  public:
    DrmDevice(int fd, std::string path);
    ~DrmDevice();
    DrmDevice(const DrmDevice&) = delete;
    DrmDevice& operator=(const DrmDevice&) = delete;

    [[nodiscard]] int fd() const { return fd_; }
    [[nodiscard]] const std::string& path() const { return path_; }
    // The kernel driver's name ("i915", "amdgpu", "nvidia-drm").
    [[nodiscard]] const std::string& driver() const { return driver_; }
    // DRM_CLIENT_CAP_ATOMIC was granted (with universal planes); else legacy modesetting.
    [[nodiscard]] bool atomic() const { return atomic_; }

  private:
    int fd_ = -1;
    std::string path_;
    std::string driver_;
    bool atomic_ = false;
};

// The connectors of a device, with the driver's own mode records beside the plain ones
// (modes[i][j] is connectors[i].modes[j]).
struct DrmConnectors {
    std::vector<ConnectorInfo> connectors;
    std::vector<std::vector<drmModeModeInfo>> modes;
};

// Reads every connector of the device `fd`; throws DisplayError "kms: <path>: ..." if the
// device has no KMS resources (a render-only node).
DrmConnectors readConnectors(int fd, const std::string& path);

// Opens `configured` ("/dev/dri/card1"), or else the first /dev/dri/card* with a connected
// connector; becomes DRM master and asks for atomic modesetting. Throws DisplayError with one
// line naming the step: "kms: no DRM device (/dev/dri/card*): ...", "kms: cannot open X: ...",
// "kms: not DRM master of X: ...".
std::unique_ptr<DrmDevice> openDrmDevice(const std::string& configured,
                                         const std::string& directory = "/dev/dri");

} // namespace steerseg::platform::kms
