#pragma once

#include <string>

namespace steerseg::gpu {

// What the current GLES context offers, as far as the solver and renderer depend on it.
struct GpuInfo {
    std::string vendor;
    std::string renderer;
    std::string version;
    std::string shadingLanguage;
    int maxComputeWorkGroupInvocations = 0;
    int maxComputeWorkGroupSize[3] = {0, 0, 0};
    int maxComputeWorkGroupCount[3] = {0, 0, 0};
    int maxComputeSharedMemoryBytes = 0;
    int maxShaderStorageBlockBytes = 0;
    int maxComputeShaderStorageBlocks = 0;
    int maxFragmentShaderStorageBlocks = 0;
    int maxComputeImageUniforms = 0;
    int max3dTextureSize = 0;
    int maxTextureSize = 0;
    int maxAtomicCounterBuffers = 0;
    // GL_OES_texture_float_linear: R32F textures may be sampled with linear filtering, so the
    // renderer can display the solver's exact scan texture instead of uploading its own copy.
    bool floatLinearFiltering = false;
};

// Reads the limits of the current context.
GpuInfo queryGpuInfo();

// The 32-bit SIMD lanes of a CPU rasterizer that names its vector width in its renderer string
// (Mesa's llvmpipe: "llvmpipe (LLVM 15.0.6, 256 bits)" -> 8); 0 for any other renderer, every
// GPU's among them.
int cpuRasterizerLanes(const std::string& renderer);

} // namespace steerseg::gpu
