#include "platform/kms/drm_device.hpp"

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <fcntl.h>
#include <filesystem>
#include <unistd.h>
#include <xf86drm.h>

namespace steerseg::platform::kms {

namespace {

std::string errnoText() {
    return std::strerror(errno);
}

// "HDMI-A" + "-" + the index the kernel gives it among connectors of its type.
std::string connectorName(const drmModeConnector& connector) {
    const char* type = drmModeGetConnectorTypeName(connector.connector_type);
    return std::string(type != nullptr ? type : "Unknown") + "-" +
           std::to_string(connector.connector_type_id);
}

ModeInfo modeInfo(const drmModeModeInfo& mode) {
    ModeInfo info;
    info.width = mode.hdisplay;
    info.height = mode.vdisplay;
    info.refreshHz = static_cast<int>(mode.vrefresh);
    info.preferred = (mode.type & DRM_MODE_TYPE_PREFERRED) != 0;
    info.name = mode.name;
    return info;
}

// Does any connector of the device report a monitor? Used only to pick a card, so errors just
// mean "no".
bool hasConnectedConnector(int fd) {
    drmModeRes* resources = drmModeGetResources(fd);
    if (resources == nullptr) {
        return false;
    }
    bool found = false;
    for (int i = 0; i < resources->count_connectors && !found; ++i) {
        drmModeConnector* c = drmModeGetConnector(fd, resources->connectors[i]);
        found = c != nullptr && c->connection == DRM_MODE_CONNECTED;
        drmModeFreeConnector(c);
    }
    drmModeFreeResources(resources);
    return found;
}

int openCard(const std::string& path) {
    const int fd = ::open(path.c_str(), O_RDWR | O_CLOEXEC);
    if (fd < 0) {
        throw DisplayError("kms: cannot open " + path + ": " + errnoText());
    }
    return fd;
}

} // namespace

DrmDevice::DrmDevice(int fd, std::string path) : fd_(fd), path_(std::move(path)) {
    drmVersion* version = drmGetVersion(fd_);
    if (version == nullptr) {
        const std::string reason = errnoText();
        ::close(fd_);
        throw DisplayError("kms: " + path_ + " is no DRM device: " + reason);
    }
    driver_ = std::string(version->name, static_cast<std::size_t>(version->name_len));
    drmFreeVersion(version);
    // Taking master fails where a display server holds it; opening as the first client on a VT
    // (the appliance's case) makes us master already.
    if (drmIsMaster(fd_) == 0 && drmSetMaster(fd_) != 0) {
        const std::string reason = errnoText();
        ::close(fd_);
        throw DisplayError("kms: not DRM master of " + path_ + ": " + reason +
                           " (is a display server running on it?)");
    }
    atomic_ = drmSetClientCap(fd_, DRM_CLIENT_CAP_UNIVERSAL_PLANES, 1) == 0 &&
              drmSetClientCap(fd_, DRM_CLIENT_CAP_ATOMIC, 1) == 0;
}

DrmDevice::~DrmDevice() {
    drmDropMaster(fd_);
    ::close(fd_);
}

DrmConnectors readConnectors(int fd, const std::string& path) {
    drmModeRes* resources = drmModeGetResources(fd);
    if (resources == nullptr) {
        throw DisplayError("kms: " + path + " has no KMS resources (" + errnoText() +
                           "; a render-only device?)");
    }
    DrmConnectors result;
    for (int i = 0; i < resources->count_connectors; ++i) {
        drmModeConnector* c = drmModeGetConnector(fd, resources->connectors[i]);
        if (c == nullptr) {
            continue; // unplugged between the two calls
        }
        ConnectorInfo info;
        info.id = c->connector_id;
        info.name = connectorName(*c);
        info.connected = c->connection == DRM_MODE_CONNECTED;
        info.mmWidth = static_cast<int>(c->mmWidth);
        info.mmHeight = static_cast<int>(c->mmHeight);
        std::vector<drmModeModeInfo> modes(c->modes, c->modes + std::max(c->count_modes, 0));
        for (const drmModeModeInfo& m : modes) {
            info.modes.push_back(modeInfo(m));
        }
        result.connectors.push_back(std::move(info));
        result.modes.push_back(std::move(modes));
        drmModeFreeConnector(c);
    }
    drmModeFreeResources(resources);
    return result;
}

std::unique_ptr<DrmDevice> openDrmDevice(const std::string& configured,
                                         const std::string& directory) {
    if (!configured.empty()) {
        return std::make_unique<DrmDevice>(openCard(configured), configured);
    }
    std::vector<std::string> cards;
    std::error_code error;
    for (const auto& entry : std::filesystem::directory_iterator(directory, error)) {
        if (entry.path().filename().string().rfind("card", 0) == 0) {
            cards.push_back(entry.path().string());
        }
    }
    if (error) {
        throw DisplayError("kms: no DRM device (" + directory + "/card*): " + directory + ": " +
                           error.message());
    }
    if (cards.empty()) {
        throw DisplayError("kms: no DRM device (" + directory + "/card*): none found");
    }
    std::sort(cards.begin(), cards.end());
    std::string tried;
    for (const std::string& card : cards) {
        const int fd = ::open(card.c_str(), O_RDWR | O_CLOEXEC);
        if (fd < 0) {
            tried += (tried.empty() ? "" : ", ") + card + ": " + errnoText();
            continue;
        }
        if (hasConnectedConnector(fd)) {
            return std::make_unique<DrmDevice>(fd, card);
        }
        ::close(fd);
        tried += (tried.empty() ? "" : ", ") + card + ": no connected connector";
    }
    throw DisplayError("kms: no DRM device with a connected connector (" + tried + ")");
}

} // namespace steerseg::platform::kms
