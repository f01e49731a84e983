#pragma once

// Reads an R32F 3D texture back to the host for tests (GLES has no glGetTexImage): a test-only
// compute pass copies it into a buffer.
#include "gpu/gl_handle.hpp"

#include <glm/glm.hpp>
#include <vector>

namespace steerseg::test {

std::vector<float> readVolumeTexture(GLuint texture, const glm::ivec3& dims);

} // namespace steerseg::test
