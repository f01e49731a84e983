#include "cli/args.hpp"
#include "cli/commands.hpp"
#include "gpu/gpu_info.hpp"
#include "platform/egl/offscreen_context.hpp"

#include <cstdio>
#include <nlohmann/json.hpp>

namespace steerseg::cli {

int runGpuInfo(std::span<const std::string> words) {
    const Args args(words, {"platform"}, {});
    const auto platform = platform::parseOffscreenPlatform(args.value("platform").value_or("auto"));
    auto context = platform::createOffscreenContext(platform);
    const gpu::GpuInfo info = gpu::queryGpuInfo();
    nlohmann::ordered_json j;
    j["egl_platform"] = context->backendName();
    j["vendor"] = info.vendor;
    j["renderer"] = info.renderer;
    j["version"] = info.version;
    j["shading_language"] = info.shadingLanguage;
    j["max_compute_work_group_invocations"] = info.maxComputeWorkGroupInvocations;
    j["max_compute_work_group_size"] = info.maxComputeWorkGroupSize;
    j["max_compute_work_group_count"] = info.maxComputeWorkGroupCount;
    j["max_compute_shared_memory_bytes"] = info.maxComputeSharedMemoryBytes;
    j["max_shader_storage_block_bytes"] = info.maxShaderStorageBlockBytes;
    j["max_compute_shader_storage_blocks"] = info.maxComputeShaderStorageBlocks;
    j["max_fragment_shader_storage_blocks"] = info.maxFragmentShaderStorageBlocks;
    j["max_compute_image_uniforms"] = info.maxComputeImageUniforms;
    j["max_3d_texture_size"] = info.max3dTextureSize;
    j["max_texture_size"] = info.maxTextureSize;
    j["max_compute_atomic_counter_buffers"] = info.maxAtomicCounterBuffers;
    j["float_linear_filtering"] = info.floatLinearFiltering;
    std::printf("%s\n", j.dump(2).c_str());
    return 0;
}

} // namespace steerseg::cli
