#include "speed_texture_readback.hpp"

#include "gpu/gl_state_guard.hpp"
#include "gpu/program.hpp"

#include <cstring>

namespace steerseg::test {

namespace {

constexpr const char* kCopy = R"(#version 310 es
precision highp float;
precision highp sampler3D;
layout(local_size_x = 64) in;
layout(binding = 0) uniform sampler3D source;
layout(std430, binding = 0) writeonly buffer Out { float values[]; };
uniform ivec3 dims;
void main() {
    int n = int(gl_GlobalInvocationID.x);
    if (n >= dims.x * dims.y * dims.z) {
        return;
    }
    ivec3 v = ivec3(n % dims.x, (n / dims.x) % dims.y, n / (dims.x * dims.y));
    values[n] = texelFetch(source, v, 0).r;
}
)";

} // namespace

std::vector<float> readVolumeTexture(GLuint texture, const glm::ivec3& dims) {
    gpu::GlStateGuard guard;
    const std::size_t count = static_cast<std::size_t>(dims.x) * static_cast<std::size_t>(dims.y) *
                              static_cast<std::size_t>(dims.z);
    const auto bytes = static_cast<GLsizeiptr>(count * sizeof(float));
    const gpu::Program program = gpu::buildComputeProgramFromSource("copy_volume.comp", kCopy);
    const gpu::Buffer out =
        gpu::createBuffer(GL_SHADER_STORAGE_BUFFER, bytes, nullptr, GL_DYNAMIC_READ);
    glUseProgram(program.id());
    glUniform3i(glGetUniformLocation(program.id(), "dims"), dims.x, dims.y, dims.z);
    glActiveTexture(GL_TEXTURE0);
    glBindTexture(GL_TEXTURE_3D, texture);
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, out.id());
    glDispatchCompute(static_cast<GLuint>((count + 63) / 64), 1, 1);
    glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
    std::vector<float> values(count);
    glBindBuffer(GL_SHADER_STORAGE_BUFFER, out.id());
    const void* mapped = glMapBufferRange(GL_SHADER_STORAGE_BUFFER, 0, bytes, GL_MAP_READ_BIT);
    if (mapped != nullptr) {
        std::memcpy(values.data(), mapped, count * sizeof(float));
        glUnmapBuffer(GL_SHADER_STORAGE_BUFFER);
    }
    return values;
}

} // namespace steerseg::test
