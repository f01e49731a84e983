#include "speed/volume_texture.hpp"

#include "common/bindings.h"
#include "core/volume.hpp"
#include "gpu/gl_counts.hpp"

#include <stdexcept>
#include <string>

namespace steerseg::speed {

gpu::Texture createVolumeTexture(const glm::ivec3& dims, const char* what) {
    while (glGetError() != GL_NO_ERROR) {
    }
    gpu::Texture texture = gpu::createTexture();
    glActiveTexture(GL_TEXTURE0 + SPEED_SOURCE_UNIT);
    glBindTexture(GL_TEXTURE_3D, texture.id());
    glTexStorage3D(GL_TEXTURE_3D, 1, GL_R32F, dims.x, dims.y, dims.z);
    if (glGetError() != GL_NO_ERROR) {
        throw std::runtime_error(std::string(what) + ": the GPU cannot hold another " +
                                 dimsText(dims) + " float texture");
    }
    glTexParameteri(GL_TEXTURE_3D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_3D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    return texture;
}

bool isVolumeTexture(GLuint texture, const glm::ivec3& dims) {
    if (texture == 0 || glIsTexture(texture) == GL_FALSE) {
        return false;
    }
    while (glGetError() != GL_NO_ERROR) {
    }
    glActiveTexture(GL_TEXTURE0 + SPEED_SOURCE_UNIT);
    glBindTexture(GL_TEXTURE_3D, texture);
    if (glGetError() != GL_NO_ERROR) {
        return false; // a texture of another target
    }
    glm::ivec3 size{0};
    GLint format = 0;
    glGetTexLevelParameteriv(GL_TEXTURE_3D, 0, GL_TEXTURE_WIDTH, &size.x);
    glGetTexLevelParameteriv(GL_TEXTURE_3D, 0, GL_TEXTURE_HEIGHT, &size.y);
    glGetTexLevelParameteriv(GL_TEXTURE_3D, 0, GL_TEXTURE_DEPTH, &size.z);
    glGetTexLevelParameteriv(GL_TEXTURE_3D, 0, GL_TEXTURE_INTERNAL_FORMAT, &format);
    return glGetError() == GL_NO_ERROR && size == dims && format == GL_R32F;
}

void runVolumePass(GLuint program, GLuint source, GLuint target, const glm::ivec3& dims) {
    glUseProgram(program);
    glActiveTexture(GL_TEXTURE0 + SPEED_SOURCE_UNIT);
    glBindTexture(GL_TEXTURE_3D, source);
    glBindImageTexture(SPEED_OUT_IMAGE_UNIT, target, 0, GL_TRUE, 0, GL_WRITE_ONLY, GL_R32F);
    glUniform3i(glGetUniformLocation(program, "volumeDims"), dims.x, dims.y, dims.z);
    gpu::dispatchCompute(static_cast<GLuint>((dims.x + 3) / 4),
                         static_cast<GLuint>((dims.y + 3) / 4),
                         static_cast<GLuint>((dims.z + 3) / 4));
    // The next pass (or the solver) fetches what this one stored.
    gpu::memoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT | GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);
}

} // namespace steerseg::speed
