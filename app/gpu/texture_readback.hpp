#pragma once

// An R32F 3D texture's values on the host, read by a compute pass into a buffer and through
// gpu::readBufferBytes (the barriers the spec asks for: the texture fetch after the shader
// writes that filled it, the copy after the pass's buffer writes). For the numerics check and
// the tests, which compare what the GPU computed with its CPU twin; not for a frame.
#include "gpu/gl.hpp"

#include <glm/glm.hpp>
#include <vector>

namespace steerseg::gpu {

// Values i fastest. The texture must be R32F (or another single-channel float format) of
// `dims`; throws GlError when the pass or the read fails.
std::vector<float> readVolumeTexture(GLuint texture, const glm::ivec3& dims);

} // namespace steerseg::gpu
