#include "speed/classifier_speed.hpp"

#include "common/bindings.h"
#include "gpu/buffer_io.hpp"
#include "gpu/gl_counts.hpp"
#include "gpu/gl_error.hpp"
#include "gpu/gl_state_guard.hpp"
#include "gpu/program.hpp"
#include "speed/classifier_features.hpp"
#include "speed/classifier_layout.h"
#include "speed/place_vote.hpp"
#include "speed/volume_texture.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace steerseg::speed {

namespace {

constexpr int kMaxSamplesPerClass = 1 << 20;
constexpr int kEvaluateGroup = 4; // classifier_evaluate.comp's local size per axis
// Slices per dispatch: 16M voxels at 512^2 a slice, a bounded share of a large scan each.
constexpr int kSlabSlices = 64;
constexpr std::size_t kWalkGroup = 64; // classifier_walk.comp's local size
// One dispatch's rows: within the 65535 groups a dimension allows.
constexpr std::size_t kMaxWalkRows = std::size_t{65535} * kWalkGroup;

double secondsSince(std::chrono::steady_clock::time_point start) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

ForestParams forestParams(const ClassifierParams& p) {
    if (p.maxSamplesPerClass < 1 || p.maxSamplesPerClass > kMaxSamplesPerClass) {
        throw std::invalid_argument("classifier speed: samples per class must be in [1, 1048576]");
    }
    ForestParams forest;
    forest.trees = p.trees;
    forest.maxDepth = p.maxDepth;
    forest.seed = p.seed;
    return forest;
}

static_assert(kPlaceVoteCell == CLASSIFIER_PLACE_CELL);

} // namespace

ClassifierSpeed::ClassifierSpeed(GLuint intensity, glm::ivec3 dims, std::span<const Example> inside,
                                 std::span<const Example> outside, const ClassifierParams& params,
                                 gpu::Texture recycled, const Volume* hostScan)
    : dims_(dims), stride_(params.featureStride), maxDepth_(params.maxDepth),
      evaluation_(params.evaluation) {
    const ForestParams forestSettings = forestParams(params);
    if (forestSettings.trees < 1 || forestSettings.trees > 256 || forestSettings.maxDepth < 1 ||
        forestSettings.maxDepth > 16) {
        // Bounded so that every voxel's walk stays cheap on the GPU (docs/speed.md).
        throw std::invalid_argument(
            "classifier speed: trees must be in [1, 256] and the depth in [1, 16]");
    }
    gpu::GlStateGuard guard;
    checkIntensityTexture(intensity, dims);
    if (hostScan != nullptr && hostScan->dims() != dims) {
        throw std::invalid_argument("classifier speed: the host scan is not of the texture's size");
    }

    auto start = std::chrono::steady_clock::now();
    const auto cap = static_cast<std::size_t>(params.maxSamplesPerClass);
    const ExampleVoxels in =
        exampleVoxels(inside, dims, cap, params.seed, "inside", params.sphereScale);
    const ExampleVoxels out =
        exampleVoxels(outside, dims, cap, static_cast<std::uint64_t>(params.seed) + 1, "outside",
                      params.sphereScale);
    std::vector<glm::ivec3> voxels = in.voxels;
    voxels.insert(voxels.end(), out.voxels.begin(), out.voxels.end());
    const std::vector<float> features =
        hostScan != nullptr ? cpuClassifierFeatures(*hostScan, voxels, stride_)
                            : gatherClassifierFeatures(intensity, dims, voxels, stride_);
    training_.featureSeconds = secondsSince(start);
    training_.insideSamples = in.voxels.size();
    training_.outsideSamples = out.voxels.size();
    training_.insideCovered = in.covered;
    training_.outsideCovered = out.covered;

    start = std::chrono::steady_clock::now();
    std::vector<std::uint8_t> labels(voxels.size(), 0);
    std::fill(labels.begin(), labels.begin() + static_cast<std::ptrdiff_t>(in.voxels.size()), 1);
    forest_ = RandomForest::train(features, labels, kClassifierFeatureCount, forestSettings);
    training_.trainSeconds = secondsSince(start);
    training_.outOfBagAccuracy = forest_.outOfBagAccuracy();

    placeVote_ = speed::placeVote(inside, outside, dims, params.placeReach, params.sphereScale);
    upload();
    texture_ = isVolumeTexture(recycled.id(), dims_)
                   ? std::move(recycled)
                   : createVolumeTexture(dims_, "classifier speed");
    if (evaluation_ == ClassifierEvaluation::OnDemand) {
        clear();
        return;
    }
    start = std::chrono::steady_clock::now();
    evaluate(intensity);
    training_.evaluateSeconds = secondsSince(start);
}

OnDemandForest ClassifierSpeed::onDemandForest() const {
    if (evaluation_ != ClassifierEvaluation::OnDemand) {
        return {};
    }
    return gpuForest();
}

OnDemandForest ClassifierSpeed::gpuForest() const {
    OnDemandForest forest{nodes_.id(), roots_.id(), static_cast<int>(forest_.roots().size()),
                          maxDepth_, place_.id()};
    forest.stride = stride_;
    return forest;
}

void bindClassifierForest(GLuint program, const OnDemandForest& forest, const glm::ivec3& dims) {
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, CLASSIFIER_NODES_BINDING, forest.nodes);
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, CLASSIFIER_ROOTS_BINDING, forest.roots);
    glProgramUniform3i(program, glGetUniformLocation(program, "classifierDims"), dims.x, dims.y,
                       dims.z);
    glProgramUniform3i(program, glGetUniformLocation(program, "classifierStride"), forest.stride.x,
                       forest.stride.y, forest.stride.z);
    glProgramUniform1i(program, glGetUniformLocation(program, "treeCount"), forest.trees);
    glProgramUniform1i(program, glGetUniformLocation(program, "maxDepth"), forest.maxDepth);
    glActiveTexture(GL_TEXTURE0 + CLASSIFIER_PLACE_UNIT);
    glBindTexture(GL_TEXTURE_3D, forest.place);
}

void ClassifierSpeed::upload() {
    const std::vector<ForestNode>& nodes = forest_.nodes();
    const std::vector<std::int32_t>& roots = forest_.roots();
    nodes_ = gpu::createBuffer(GL_SHADER_STORAGE_BUFFER,
                               static_cast<GLsizeiptr>(nodes.size() * sizeof(ForestNode)),
                               nodes.data(), GL_STATIC_DRAW);
    roots_ = gpu::createBuffer(GL_SHADER_STORAGE_BUFFER,
                               static_cast<GLsizeiptr>(roots.size() * sizeof(std::int32_t)),
                               roots.data(), GL_STATIC_DRAW);
    // R16F: filterable in GLES 3.1 core (R32F is not), and a vote needs no more.
    place_ = gpu::createTexture();
    glActiveTexture(GL_TEXTURE0 + CLASSIFIER_PLACE_UNIT);
    glBindTexture(GL_TEXTURE_3D, place_.id());
    const glm::ivec3 cells = placeVote_.dims;
    glTexStorage3D(GL_TEXTURE_3D, 1, GL_R16F, cells.x, cells.y, cells.z);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
    glTexSubImage3D(GL_TEXTURE_3D, 0, 0, 0, 0, cells.x, cells.y, cells.z, GL_RED, GL_FLOAT,
                    placeVote_.values.data());
    glTexParameteri(GL_TEXTURE_3D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_3D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_3D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glTexParameteri(GL_TEXTURE_3D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    glTexParameteri(GL_TEXTURE_3D, GL_TEXTURE_WRAP_R, GL_CLAMP_TO_EDGE);
    gpu::checkGl("uploading the classifier's place vote");
}

// 0 is "no preference" to a speed view; a slice at a time keeps the host's zeros small.
void ClassifierSpeed::clear() {
    const std::vector<float> zeros(static_cast<std::size_t>(dims_.x) *
                                   static_cast<std::size_t>(dims_.y));
    glActiveTexture(GL_TEXTURE0 + SPEED_SOURCE_UNIT);
    glBindTexture(GL_TEXTURE_3D, texture_.id());
    glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
    for (int z = 0; z < dims_.z; ++z) {
        glTexSubImage3D(GL_TEXTURE_3D, 0, 0, 0, z, dims_.x, dims_.y, 1, GL_RED, GL_FLOAT,
                        zeros.data());
    }
    gpu::checkGl("clearing the classifier speed");
}

void ClassifierSpeed::evaluate(GLuint intensity) {
    const gpu::Program program = gpu::buildComputeProgram("speed/classifier_evaluate.comp");
    glUseProgram(program.id());
    bindClassifierForest(program.id(), gpuForest(), dims_);
    glActiveTexture(GL_TEXTURE0 + SPEED_SOURCE_UNIT);
    glBindTexture(GL_TEXTURE_3D, intensity);
    glBindImageTexture(SPEED_OUT_IMAGE_UNIT, texture_.id(), 0, GL_TRUE, 0, GL_WRITE_ONLY, GL_R32F);
    auto groups = [](int n) {
        return static_cast<GLuint>((n + kEvaluateGroup - 1) / kEvaluateGroup);
    };
    const GLint zOffsetAt = glGetUniformLocation(program.id(), "zOffset");
    for (int z = 0; z < dims_.z; z += kSlabSlices) {
        glUniform1i(zOffsetAt, z);
        gpu::dispatchCompute(groups(dims_.x), groups(dims_.y),
                             groups(std::min(kSlabSlices, dims_.z - z)));
        glFlush(); // each slab its own submission
    }
    gpu::memoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT | GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);
    // Finished here, so that the timing is the evaluation's and the solver's first read waits
    // on nothing.
    gpu::finish();
    gpu::checkGl("evaluating the classifier speed");
}

std::vector<float> ClassifierSpeed::walkOnGpu(std::span<const float> features) const {
    if (features.size() % kClassifierFeatureCount != 0) {
        throw std::invalid_argument("classifier speed: feature rows of " +
                                    std::to_string(kClassifierFeatureCount) + " values each");
    }
    const std::size_t rows = features.size() / kClassifierFeatureCount;
    if (rows == 0) {
        return {};
    }
    if (rows > kMaxWalkRows) {
        throw std::invalid_argument("classifier speed: at most " + std::to_string(kMaxWalkRows) +
                                    " feature rows a walk");
    }
    gpu::GlStateGuard guard;
    const gpu::Program program = gpu::buildComputeProgram("speed/classifier_walk.comp");
    glUseProgram(program.id());
    bindClassifierForest(program.id(), gpuForest(), dims_);
    const gpu::Buffer in =
        gpu::createBuffer(GL_SHADER_STORAGE_BUFFER, static_cast<GLsizeiptr>(features.size_bytes()),
                          features.data(), GL_STATIC_DRAW);
    // NaN until the dispatch writes a look, as the gather's rows.
    std::vector<float> looks(rows, std::numeric_limits<float>::quiet_NaN());
    const gpu::Buffer out =
        gpu::createBuffer(GL_SHADER_STORAGE_BUFFER, static_cast<GLsizeiptr>(rows * sizeof(float)),
                          looks.data(), GL_STREAM_READ);
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, CLASSIFIER_FEATURES_BINDING, in.id());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, CLASSIFIER_SAMPLES_BINDING, out.id());
    glUniform1i(glGetUniformLocation(program.id(), "rowCount"), static_cast<GLint>(rows));
    gpu::dispatchCompute(static_cast<GLuint>((rows + kWalkGroup - 1) / kWalkGroup), 1, 1);
    gpu::readBufferBytes(out, 0, looks.data(), looks.size() * sizeof(float),
                         "the classifier's walk");
    gpu::checkGl("walking the classifier's forest");
    const auto unwritten = static_cast<std::size_t>(
        std::count_if(looks.begin(), looks.end(), [](float f) { return !std::isfinite(f); }));
    if (unwritten > 0) {
        throw gpu::GpuNumericsError("classifier speed: the GPU's walk left " +
                                    std::to_string(unwritten) + " of " + std::to_string(rows) +
                                    " looks unwritten or not finite");
    }
    return looks;
}

} // namespace steerseg::speed
