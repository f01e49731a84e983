#include "speed/classifier_features.hpp"

#include "common/bindings.h"
#include "core/volume.hpp"
#include "gpu/buffer_io.hpp"
#include "gpu/gl_counts.hpp"
#include "gpu/gl_error.hpp"
#include "gpu/gl_handle.hpp"
#include "gpu/gl_state_guard.hpp"
#include "gpu/program.hpp"
#include "speed/classifier_gather_fault.hpp"
#include "speed/classifier_layout.h"
#include "speed/volume_texture.hpp"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

namespace steerseg::speed {

static_assert(kClassifierFeatureCount == CLASSIFIER_FEATURE_COUNT,
              "the C++ and GLSL feature counts must agree");

namespace {
std::atomic<bool> reverseRows{false};
constexpr int kGroupSize = 64; // classifier_gather.comp's local size
// Samples per dispatch: within the 65535 groups a dimension allows.
constexpr std::size_t kMaxDispatchSamples = std::size_t{65535} * kGroupSize;
} // namespace

void fault::reverseGatheredRows(bool on) {
    reverseRows = on;
}

void checkIntensityTexture(GLuint intensity, glm::ivec3 dims) {
    gpu::GlStateGuard guard;
    if (intensity == 0 || glIsTexture(intensity) == GL_FALSE) {
        throw std::invalid_argument("classifier speed: the intensity texture is not a texture");
    }
    if (!isVolumeTexture(intensity, dims)) {
        throw std::invalid_argument("classifier speed: the intensity texture is not R32F of " +
                                    dimsText(dims) + " voxels");
    }
}

std::vector<float> gatherClassifierFeatures(GLuint intensity, glm::ivec3 dims,
                                            std::span<const glm::ivec3> voxels, glm::ivec3 stride) {
    if (glm::any(glm::lessThan(stride, glm::ivec3(1)))) {
        throw std::invalid_argument("classifier features: a stride below one voxel");
    }
    gpu::GlStateGuard guard;
    std::vector<float> features(voxels.size() * kClassifierFeatureCount);
    if (voxels.empty()) {
        return features;
    }
    std::vector<glm::ivec4> coords(voxels.size());
    for (std::size_t n = 0; n < voxels.size(); ++n) {
        const glm::ivec3 v = voxels[n];
        if (glm::any(glm::lessThan(v, glm::ivec3(0))) || glm::any(glm::greaterThanEqual(v, dims))) {
            throw std::invalid_argument("classifier speed: a sample voxel lies outside the scan");
        }
        coords[n] = glm::ivec4(v, 0);
    }
    const gpu::Program program = gpu::buildComputeProgram("speed/classifier_gather.comp");
    const gpu::Buffer in = gpu::createBuffer(
        GL_SHADER_STORAGE_BUFFER, static_cast<GLsizeiptr>(coords.size() * sizeof(glm::ivec4)),
        coords.data(), GL_STATIC_DRAW);
    // NaN until the dispatch writes a row: stale or unwritten memory then reads as what it is.
    std::fill(features.begin(), features.end(), std::numeric_limits<float>::quiet_NaN());
    const gpu::Buffer out = gpu::createBuffer(
        GL_SHADER_STORAGE_BUFFER, static_cast<GLsizeiptr>(features.size() * sizeof(float)),
        features.data(), GL_STREAM_READ);
    glUseProgram(program.id());
    glActiveTexture(GL_TEXTURE0 + SPEED_SOURCE_UNIT);
    glBindTexture(GL_TEXTURE_3D, intensity);
    glUniform3i(glGetUniformLocation(program.id(), "classifierDims"), dims.x, dims.y, dims.z);
    glUniform3i(glGetUniformLocation(program.id(), "classifierStride"), stride.x, stride.y,
                stride.z);
    const GLint countAt = glGetUniformLocation(program.id(), "sampleCount");
    for (std::size_t first = 0; first < coords.size(); first += kMaxDispatchSamples) {
        const std::size_t count = std::min(kMaxDispatchSamples, coords.size() - first);
        glBindBufferRange(GL_SHADER_STORAGE_BUFFER, CLASSIFIER_SAMPLES_BINDING, in.id(),
                          static_cast<GLintptr>(first * sizeof(glm::ivec4)),
                          static_cast<GLsizeiptr>(count * sizeof(glm::ivec4)));
        glBindBufferRange(GL_SHADER_STORAGE_BUFFER, CLASSIFIER_FEATURES_BINDING, out.id(),
                          static_cast<GLintptr>(first * kClassifierFeatureCount * sizeof(float)),
                          static_cast<GLsizeiptr>(count * kClassifierFeatureCount * sizeof(float)));
        glUniform1i(countAt, static_cast<GLint>(count));
        gpu::dispatchCompute(static_cast<GLuint>((count + kGroupSize - 1) / kGroupSize), 1, 1);
    }
    gpu::readBufferBytes(out, 0, features.data(), features.size() * sizeof(float),
                         "the classifier's sample features");
    gpu::checkGl("gathering the classifier's sample features");
    if (reverseRows) {
        for (std::size_t a = 0, b = voxels.size() - 1; a < b; ++a, --b) {
            std::swap_ranges(
                features.begin() + static_cast<std::ptrdiff_t>(a * kClassifierFeatureCount),
                features.begin() + static_cast<std::ptrdiff_t>((a + 1) * kClassifierFeatureCount),
                features.begin() + static_cast<std::ptrdiff_t>(b * kClassifierFeatureCount));
        }
    }
    std::size_t unwritten = 0;
    for (std::size_t row = 0; row < voxels.size(); ++row) {
        const auto first =
            features.begin() + static_cast<std::ptrdiff_t>(row * kClassifierFeatureCount);
        unwritten += std::all_of(first, first + kClassifierFeatureCount,
                                 [](float f) { return std::isfinite(f); })
                         ? 0
                         : 1;
    }
    if (unwritten > 0) {
        throw gpu::GpuNumericsError(
            "classifier speed: the GPU returned " + std::to_string(unwritten) + " of " +
            std::to_string(voxels.size()) + " training samples' features unwritten or not finite");
    }
    return features;
}

} // namespace steerseg::speed
