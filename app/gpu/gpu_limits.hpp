#pragma once

#include <cstddef>
#include <cstdint>
#include <string>

namespace steerseg::gpu {

// The limits of the current GPU that decide whether a scan, its level set and its views fit,
// as the scan texture, the solver and the renderer check them before allocating
// (docs/large-scans.md). Read from the current context when one of them is set up, then
// lowered by any TestGpuLimits in force: tests run the refusal paths for real on a small volume
// instead of faking GL.
struct GpuLimits {
    int max3dTextureSize = 0;                              // GL_MAX_3D_TEXTURE_SIZE
    int maxTextureSize = 0;                                // GL_MAX_TEXTURE_SIZE
    std::size_t maxShaderStorageBlockBytes = 0;            // GL_MAX_SHADER_STORAGE_BLOCK_SIZE
    std::uint32_t maxComputeWorkGroupCount[3] = {0, 0, 0}; // GL_MAX_COMPUTE_WORK_GROUP_COUNT
};

// The current context's limits, lowered by the innermost TestGpuLimits.
GpuLimits gpuLimits();

// Lowers gpuLimits() to `lower` (fields left 0 keep the context's value) for its lifetime.
// For tests; process-wide, so not for concurrent use.
class TestGpuLimits {
  public:
    explicit TestGpuLimits(const GpuLimits& lower);
    ~TestGpuLimits();
    TestGpuLimits(const TestGpuLimits&) = delete;
    TestGpuLimits& operator=(const TestGpuLimits&) = delete;

  private:
    const GpuLimits* previous_;
    GpuLimits lower_;
};

// "512x512x1000".
std::string sizeText(int x, int y, int z);
// Bytes as "1000 MiB", "2.0 GiB" or "512 KiB", for messages.
std::string bytesText(double bytes);

} // namespace steerseg::gpu
