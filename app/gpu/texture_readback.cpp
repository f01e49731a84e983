#include "gpu/texture_readback.hpp"

#include "common/bindings.h"
#include "gpu/buffer_io.hpp"
#include "gpu/gl_counts.hpp"
#include "gpu/gl_error.hpp"
#include "gpu/gl_handle.hpp"
#include "gpu/gl_state_guard.hpp"
#include "gpu/program.hpp"

#include <algorithm>
#include <stdexcept>

namespace steerseg::gpu {

namespace {
constexpr int kGroup = 4;       // read_volume.comp's local size per axis
constexpr int kSlabSlices = 64; // slices per dispatch
} // namespace

std::vector<float> readVolumeTexture(GLuint texture, const glm::ivec3& dims) {
    if (glm::any(glm::lessThan(dims, glm::ivec3(1)))) {
        throw std::invalid_argument("reading a volume texture: empty dimensions");
    }
    GlStateGuard guard;
    const std::size_t count = static_cast<std::size_t>(dims.x) * static_cast<std::size_t>(dims.y) *
                              static_cast<std::size_t>(dims.z);
    const Program program = buildComputeProgram("gpu/read_volume.comp");
    const Buffer out =
        createBuffer(GL_SHADER_STORAGE_BUFFER, static_cast<GLsizeiptr>(count * sizeof(float)),
                     nullptr, GL_STREAM_READ);
    // Whatever pass wrote the texture through an image is seen by this one's fetches.
    gpu::memoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT);
    glUseProgram(program.id());
    glActiveTexture(GL_TEXTURE0 + READ_VOLUME_UNIT);
    glBindTexture(GL_TEXTURE_3D, texture);
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, READ_VOLUME_BINDING, out.id());
    glUniform3i(glGetUniformLocation(program.id(), "volumeDims"), dims.x, dims.y, dims.z);
    const GLint zOffsetAt = glGetUniformLocation(program.id(), "zOffset");
    const auto groups = [](int n) { return static_cast<GLuint>((n + kGroup - 1) / kGroup); };
    for (int z = 0; z < dims.z; z += kSlabSlices) {
        glUniform1i(zOffsetAt, z);
        gpu::dispatchCompute(groups(dims.x), groups(dims.y),
                             groups(std::min(kSlabSlices, dims.z - z)));
    }
    checkGl("reading a volume texture back");
    return readBuffer<float>(out, count, "a volume texture's values");
}

} // namespace steerseg::gpu
