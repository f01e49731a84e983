#include "platform/kms/gbm_surface.hpp"

#include "platform/display.hpp"

#include <array>
#include <cerrno>
#include <cstring>
#include <xf86drm.h>
#include <xf86drmMode.h>

namespace steerseg::platform::kms {

namespace {

struct FramebufferRecord {
    int fd;
    std::uint32_t id;
};

// GBM calls this when it destroys a buffer, so each framebuffer lives exactly as long as its bo.
void destroyFramebuffer(gbm_bo* /*bo*/, void* data) {
    auto* record = static_cast<FramebufferRecord*>(data);
    drmModeRmFB(record->fd, record->id);
    delete record;
}

} // namespace

GbmSurface::GbmSurface(int fd, const std::string& path, int width, int height) : fd_(fd) {
    device_ = gbm_create_device(fd);
    if (device_ == nullptr) {
        throw DisplayError("kms: no GBM device on " + path + ": " + std::strerror(errno));
    }
    surface_ = gbm_surface_create(device_, static_cast<std::uint32_t>(width),
                                  static_cast<std::uint32_t>(height), format(),
                                  GBM_BO_USE_SCANOUT | GBM_BO_USE_RENDERING);
    if (surface_ == nullptr) {
        gbm_device_destroy(device_);
        throw DisplayError("kms: no GBM surface of " + std::to_string(width) + "x" +
                           std::to_string(height) + " XRGB8888 for scanout on " + path + ": " +
                           std::strerror(errno));
    }
}

GbmSurface::~GbmSurface() {
    gbm_surface_destroy(surface_);
    gbm_device_destroy(device_);
}

gbm_bo* GbmSurface::lockFront() {
    return gbm_surface_lock_front_buffer(surface_);
}

void GbmSurface::release(gbm_bo* bo) {
    if (bo != nullptr) {
        gbm_surface_release_buffer(surface_, bo);
    }
}

std::uint32_t GbmSurface::framebufferOf(gbm_bo* bo) {
    if (auto* record = static_cast<FramebufferRecord*>(gbm_bo_get_user_data(bo))) {
        return record->id;
    }
    const std::uint32_t width = gbm_bo_get_width(bo);
    const std::uint32_t height = gbm_bo_get_height(bo);
    std::array<std::uint32_t, 4> handles{};
    std::array<std::uint32_t, 4> pitches{};
    std::array<std::uint32_t, 4> offsets{};
    const int planes = gbm_bo_get_plane_count(bo);
    for (int p = 0; p < planes && p < 4; ++p) {
        const auto i = static_cast<std::size_t>(p);
        handles[i] = gbm_bo_get_handle_for_plane(bo, p).u32;
        pitches[i] = gbm_bo_get_stride_for_plane(bo, p);
        offsets[i] = gbm_bo_get_offset(bo, p);
    }
    std::uint32_t id = 0;
    if (drmModeAddFB2(fd_, width, height, gbm_bo_get_format(bo), handles.data(), pitches.data(),
                      offsets.data(), &id, 0) != 0) {
        const std::string reason = std::strerror(errno);
        // Older drivers lack AddFB2; the depth/bpp call covers XRGB8888.
        if (drmModeAddFB(fd_, width, height, 24, 32, gbm_bo_get_stride(bo),
                         gbm_bo_get_handle(bo).u32, &id) != 0) {
            throw DisplayError("kms: drmModeAddFB2 failed: " + reason);
        }
    }
    gbm_bo_set_user_data(bo, new FramebufferRecord{fd_, id}, destroyFramebuffer);
    return id;
}

} // namespace steerseg::platform::kms
