#include "platform/kms/modeset.hpp"

#include <cerrno>
#include <cstring>
#include <xf86drm.h>

namespace steerseg::platform::kms {

namespace {

// The id of property `name` on object `id`, 0 where the object has none.
std::uint32_t propertyId(int fd, std::uint32_t id, std::uint32_t type, const char* name) {
    drmModeObjectProperties* props = drmModeObjectGetProperties(fd, id, type);
    if (props == nullptr) {
        return 0;
    }
    std::uint32_t found = 0;
    for (std::uint32_t i = 0; i < props->count_props && found == 0; ++i) {
        drmModePropertyRes* prop = drmModeGetProperty(fd, props->props[i]);
        if (prop != nullptr && std::strcmp(prop->name, name) == 0) {
            found = prop->prop_id;
        }
        drmModeFreeProperty(prop);
    }
    drmModeFreeObjectProperties(props);
    return found;
}

// The value of property `name` on object `id`, or `fallback`.
std::uint64_t propertyValue(int fd, std::uint32_t id, std::uint32_t type, const char* name,
                            std::uint64_t fallback) {
    drmModeObjectProperties* props = drmModeObjectGetProperties(fd, id, type);
    if (props == nullptr) {
        return fallback;
    }
    std::uint64_t value = fallback;
    for (std::uint32_t i = 0; i < props->count_props; ++i) {
        drmModePropertyRes* prop = drmModeGetProperty(fd, props->props[i]);
        if (prop != nullptr && std::strcmp(prop->name, name) == 0) {
            value = props->prop_values[i];
        }
        drmModeFreeProperty(prop);
    }
    drmModeFreeObjectProperties(props);
    return value;
}

// The CRTC the connector's current encoder drives, else the first CRTC any of its encoders can
// drive. Returns {id, index in the resources' CRTC list}, or {0, -1}.
std::pair<std::uint32_t, int> findCrtc(int fd, std::uint32_t connectorId) {
    drmModeRes* resources = drmModeGetResources(fd);
    drmModeConnector* connector = drmModeGetConnector(fd, connectorId);
    std::pair<std::uint32_t, int> result{0, -1};
    if (resources == nullptr || connector == nullptr) {
        drmModeFreeConnector(connector);
        drmModeFreeResources(resources);
        return result;
    }
    const auto indexOf = [resources](std::uint32_t crtc) {
        for (int i = 0; i < resources->count_crtcs; ++i) {
            if (resources->crtcs[i] == crtc) {
                return i;
            }
        }
        return -1;
    };
    if (connector->encoder_id != 0) {
        drmModeEncoder* encoder = drmModeGetEncoder(fd, connector->encoder_id);
        if (encoder != nullptr && encoder->crtc_id != 0) {
            result = {encoder->crtc_id, indexOf(encoder->crtc_id)};
        }
        drmModeFreeEncoder(encoder);
    }
    for (int e = 0; e < connector->count_encoders && result.first == 0; ++e) {
        drmModeEncoder* encoder = drmModeGetEncoder(fd, connector->encoders[e]);
        if (encoder == nullptr) {
            continue;
        }
        for (int i = 0; i < resources->count_crtcs && i < 32; ++i) {
            if ((encoder->possible_crtcs & (1U << static_cast<unsigned>(i))) != 0) {
                result = {resources->crtcs[i], i};
                break;
            }
        }
        drmModeFreeEncoder(encoder);
    }
    drmModeFreeConnector(connector);
    drmModeFreeResources(resources);
    return result;
}

} // namespace

Modeset::Modeset(const DrmDevice& device, const ConnectorInfo& connector,
                 const drmModeModeInfo& mode)
    : fd_(device.fd()), connectorName_(connector.name), connectorId_(connector.id), mode_(mode) {
    const auto [crtc, index] = findCrtc(fd_, connectorId_);
    if (crtc == 0) {
        throw DisplayError("kms: no CRTC for connector " + connectorName_ + " on " + device.path());
    }
    crtcId_ = crtc;
    crtcIndex_ = index;
    saved_ = drmModeGetCrtc(fd_, crtcId_);
    atomic_ = device.atomic() && findAtomicObjects();
}

Modeset::~Modeset() {
    if (saved_ != nullptr) {
        // Give the console back what it showed (fbcon's framebuffer), as kmscube's users expect.
        if (saved_->buffer_id != 0) {
            drmModeSetCrtc(fd_, saved_->crtc_id, saved_->buffer_id, saved_->x, saved_->y,
                           &connectorId_, 1, &saved_->mode);
        }
        drmModeFreeCrtc(saved_);
    }
    if (modeBlob_ != 0) {
        drmModeDestroyPropertyBlob(fd_, modeBlob_);
    }
}

bool Modeset::findAtomicObjects() {
    drmModePlaneRes* planes = drmModeGetPlaneResources(fd_);
    if (planes == nullptr) {
        return false;
    }
    for (std::uint32_t i = 0; i < planes->count_planes && planeId_ == 0; ++i) {
        drmModePlane* plane = drmModeGetPlane(fd_, planes->planes[i]);
        if (plane == nullptr) {
            continue;
        }
        const bool forCrtc =
            crtcIndex_ >= 0 && crtcIndex_ < 32 &&
            (plane->possible_crtcs & (1U << static_cast<unsigned>(crtcIndex_))) != 0;
        if (forCrtc && propertyValue(fd_, plane->plane_id, DRM_MODE_OBJECT_PLANE, "type", 0) ==
                           DRM_PLANE_TYPE_PRIMARY) {
            planeId_ = plane->plane_id;
        }
        drmModeFreePlane(plane);
    }
    drmModeFreePlaneResources(planes);
    if (planeId_ == 0) {
        return false;
    }
    const auto plane = [this](const char* name) {
        return propertyId(fd_, planeId_, DRM_MODE_OBJECT_PLANE, name);
    };
    plane_ = {plane("FB_ID"), plane("CRTC_ID"), plane("SRC_X"),  plane("SRC_Y"),  plane("SRC_W"),
              plane("SRC_H"), plane("CRTC_X"),  plane("CRTC_Y"), plane("CRTC_W"), plane("CRTC_H")};
    connectorCrtcProp_ = propertyId(fd_, connectorId_, DRM_MODE_OBJECT_CONNECTOR, "CRTC_ID");
    crtcModeProp_ = propertyId(fd_, crtcId_, DRM_MODE_OBJECT_CRTC, "MODE_ID");
    crtcActiveProp_ = propertyId(fd_, crtcId_, DRM_MODE_OBJECT_CRTC, "ACTIVE");
    const std::uint32_t needed[] = {
        plane_.fbId,        plane_.crtcId, plane_.srcX,    plane_.srcY,  plane_.srcW,
        plane_.srcH,        plane_.crtcX,  plane_.crtcY,   plane_.crtcW, plane_.crtcH,
        connectorCrtcProp_, crtcModeProp_, crtcActiveProp_};
    for (std::uint32_t id : needed) {
        if (id == 0) {
            return false;
        }
    }
    return drmModeCreatePropertyBlob(fd_, &mode_, sizeof mode_, &modeBlob_) == 0;
}

int Modeset::commitAtomic(std::uint32_t fb, std::uint32_t flags, void* userData) {
    drmModeAtomicReq* request = drmModeAtomicAlloc();
    if (request == nullptr) {
        return ENOMEM;
    }
    if ((flags & DRM_MODE_ATOMIC_ALLOW_MODESET) != 0) {
        drmModeAtomicAddProperty(request, connectorId_, connectorCrtcProp_, crtcId_);
        drmModeAtomicAddProperty(request, crtcId_, crtcModeProp_, modeBlob_);
        drmModeAtomicAddProperty(request, crtcId_, crtcActiveProp_, 1);
    }
    const std::uint64_t w = mode_.hdisplay;
    const std::uint64_t h = mode_.vdisplay;
    drmModeAtomicAddProperty(request, planeId_, plane_.fbId, fb);
    drmModeAtomicAddProperty(request, planeId_, plane_.crtcId, crtcId_);
    drmModeAtomicAddProperty(request, planeId_, plane_.srcX, 0);
    drmModeAtomicAddProperty(request, planeId_, plane_.srcY, 0);
    drmModeAtomicAddProperty(request, planeId_, plane_.srcW, w << 16U); // 16.16 fixed point
    drmModeAtomicAddProperty(request, planeId_, plane_.srcH, h << 16U);
    drmModeAtomicAddProperty(request, planeId_, plane_.crtcX, 0);
    drmModeAtomicAddProperty(request, planeId_, plane_.crtcY, 0);
    drmModeAtomicAddProperty(request, planeId_, plane_.crtcW, w);
    drmModeAtomicAddProperty(request, planeId_, plane_.crtcH, h);
    const int result = drmModeAtomicCommit(fd_, request, flags, userData);
    const int error = result == 0 ? 0 : (errno != 0 ? errno : EINVAL);
    drmModeAtomicFree(request);
    return error;
}

void Modeset::show(std::uint32_t fb) {
    if (atomic_) {
        const int error = commitAtomic(fb, DRM_MODE_ATOMIC_ALLOW_MODESET, nullptr);
        if (error == 0) {
            return;
        }
        // Some drivers advertise atomic and then refuse the first commit; legacy still works.
        atomic_ = false;
    }
    if (drmModeSetCrtc(fd_, crtcId_, fb, 0, 0, &connectorId_, 1, &mode_) != 0) {
        throw DisplayError("kms: setting mode " + std::string(mode_.name) + " on " +
                           connectorName_ + " failed: " + std::strerror(errno));
    }
}

int Modeset::flip(std::uint32_t fb, void* userData) {
    if (atomic_) {
        return commitAtomic(fb, DRM_MODE_PAGE_FLIP_EVENT | DRM_MODE_ATOMIC_NONBLOCK, userData);
    }
    if (drmModePageFlip(fd_, crtcId_, fb, DRM_MODE_PAGE_FLIP_EVENT, userData) != 0) {
        return errno != 0 ? errno : EINVAL;
    }
    return 0;
}

} // namespace steerseg::platform::kms
