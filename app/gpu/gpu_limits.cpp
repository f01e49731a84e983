#include "gpu/gpu_limits.hpp"

#include "gpu/gl.hpp"

#include <algorithm>
#include <cstdio>

namespace steerseg::gpu {

namespace {

const GpuLimits* lowered = nullptr;

int glInt(GLenum name) {
    GLint v = 0;
    glGetIntegerv(name, &v);
    return v;
}

template <typename T> void lower(T& value, T limit) {
    if (limit > 0) {
        value = std::min(value, limit);
    }
}

} // namespace

GpuLimits gpuLimits() {
    GpuLimits l;
    l.max3dTextureSize = glInt(GL_MAX_3D_TEXTURE_SIZE);
    l.maxTextureSize = glInt(GL_MAX_TEXTURE_SIZE);
    // GLint64: drivers with more than 2 GiB of storage block report it only there.
    GLint64 block = 0;
    glGetInteger64v(GL_MAX_SHADER_STORAGE_BLOCK_SIZE, &block);
    l.maxShaderStorageBlockBytes = static_cast<std::size_t>(std::max<GLint64>(block, 0));
    for (GLuint i = 0; i < 3; ++i) {
        GLint count = 0;
        glGetIntegeri_v(GL_MAX_COMPUTE_WORK_GROUP_COUNT, i, &count);
        l.maxComputeWorkGroupCount[i] = static_cast<std::uint32_t>(std::max(count, 0));
    }
    if (lowered != nullptr) {
        lower(l.max3dTextureSize, lowered->max3dTextureSize);
        lower(l.maxTextureSize, lowered->maxTextureSize);
        lower(l.maxShaderStorageBlockBytes, lowered->maxShaderStorageBlockBytes);
        for (int i = 0; i < 3; ++i) {
            lower(l.maxComputeWorkGroupCount[i], lowered->maxComputeWorkGroupCount[i]);
        }
    }
    return l;
}

TestGpuLimits::TestGpuLimits(const GpuLimits& lower) : previous_(lowered), lower_(lower) {
    lowered = &lower_;
}

TestGpuLimits::~TestGpuLimits() {
    lowered = previous_;
}

std::string sizeText(int x, int y, int z) {
    return std::to_string(x) + "x" + std::to_string(y) + "x" + std::to_string(z);
}

std::string bytesText(double bytes) {
    char buf[32];
    if (bytes >= 10.0 * (1 << 30)) {
        std::snprintf(buf, sizeof buf, "%.0f GiB", bytes / (1 << 30));
    } else if (bytes >= (1 << 30)) {
        std::snprintf(buf, sizeof buf, "%.1f GiB", bytes / (1 << 30));
    } else if (bytes >= (1 << 20)) {
        std::snprintf(buf, sizeof buf, "%.0f MiB", bytes / (1 << 20));
    } else if (bytes >= 1024) {
        std::snprintf(buf, sizeof buf, "%.0f KiB", bytes / 1024);
    } else {
        std::snprintf(buf, sizeof buf, "%.0f bytes", bytes);
    }
    return buf;
}

} // namespace steerseg::gpu
