#include "gpu/gpu_info.hpp"

#include "gpu/gl.hpp"

#include <cctype>
#include <cstring>

namespace steerseg::gpu {

namespace {

std::string glString(GLenum name) {
    const auto* s = reinterpret_cast<const char*>(glGetString(name));
    return s != nullptr ? s : "";
}

int glInt(GLenum name) {
    GLint v = 0;
    glGetIntegerv(name, &v);
    return v;
}

bool hasExtension(const char* name) {
    const int count = glInt(GL_NUM_EXTENSIONS);
    for (int i = 0; i < count; ++i) {
        const auto* e =
            reinterpret_cast<const char*>(glGetStringi(GL_EXTENSIONS, static_cast<GLuint>(i)));
        if (e != nullptr && std::strcmp(e, name) == 0) {
            return true;
        }
    }
    return false;
}

} // namespace

GpuInfo queryGpuInfo() {
    GpuInfo info;
    info.vendor = glString(GL_VENDOR);
    info.renderer = glString(GL_RENDERER);
    info.version = glString(GL_VERSION);
    info.shadingLanguage = glString(GL_SHADING_LANGUAGE_VERSION);
    info.maxComputeWorkGroupInvocations = glInt(GL_MAX_COMPUTE_WORK_GROUP_INVOCATIONS);
    for (GLuint i = 0; i < 3; ++i) {
        glGetIntegeri_v(GL_MAX_COMPUTE_WORK_GROUP_SIZE, i, &info.maxComputeWorkGroupSize[i]);
        glGetIntegeri_v(GL_MAX_COMPUTE_WORK_GROUP_COUNT, i, &info.maxComputeWorkGroupCount[i]);
    }
    info.maxComputeSharedMemoryBytes = glInt(GL_MAX_COMPUTE_SHARED_MEMORY_SIZE);
    info.maxShaderStorageBlockBytes = glInt(GL_MAX_SHADER_STORAGE_BLOCK_SIZE);
    info.maxComputeShaderStorageBlocks = glInt(GL_MAX_COMPUTE_SHADER_STORAGE_BLOCKS);
    info.maxFragmentShaderStorageBlocks = glInt(GL_MAX_FRAGMENT_SHADER_STORAGE_BLOCKS);
    info.maxComputeImageUniforms = glInt(GL_MAX_COMPUTE_IMAGE_UNIFORMS);
    info.max3dTextureSize = glInt(GL_MAX_3D_TEXTURE_SIZE);
    info.maxTextureSize = glInt(GL_MAX_TEXTURE_SIZE);
    info.maxAtomicCounterBuffers = glInt(GL_MAX_COMPUTE_ATOMIC_COUNTER_BUFFERS);
    info.floatLinearFiltering = hasExtension("GL_OES_texture_float_linear");
    return info;
}

int cpuRasterizerLanes(const std::string& renderer) {
    if (renderer.rfind("llvmpipe", 0) != 0) {
        return 0;
    }
    const std::size_t bits = renderer.find(" bits)");
    std::size_t start = bits;
    while (start > 0 && std::isdigit(static_cast<unsigned char>(renderer[start - 1])) != 0) {
        --start;
    }
    if (bits == std::string::npos || start == bits || bits - start > 5) {
        return 0;
    }
    return std::stoi(renderer.substr(start, bits - start)) / 32;
}

} // namespace steerseg::gpu
