#pragma once

// The classification speed (issue 13, docs/speed.md): the operator's inside and outside examples
// train a random forest over per-voxel features (GPU gather, CPU training), and the forest,
// evaluated at every voxel on the GPU, gives the data speed P(inside) - P(outside) in [-1, 1]
// as an R32F 3D texture for the solver; where the forest is unsure, the examples near the voxel
// decide (speed/place_vote, issue 27). Needs a current GLES 3.1 context for its whole life.
#include "core/volume.hpp"
#include "gpu/gl_handle.hpp"
#include "speed/example_voxels.hpp"
#include "speed/place_vote.hpp"
#include "speed/random_forest.hpp"
#include "speed/speed_inputs.hpp"

#include <cstddef>
#include <cstdint>
#include <glm/glm.hpp>
#include <span>
#include <utility>

namespace steerseg::speed {

// Everywhere: the forest at every voxel now (its cost follows the scan: about 30 s at 256^3 on
// llvmpipe). OnDemand: the texture starts at 0 (no preference) and the solver evaluates each
// brick as the front first reaches it (onDemandForest(), solver/evaluate_speed.comp), so the
// cost follows the region the surface sweeps.
enum class ClassifierEvaluation { Everywhere, OnDemand };

struct ClassifierParams {
    ClassifierEvaluation evaluation = ClassifierEvaluation::Everywhere;
    int trees = 32;
    int maxDepth = 10;
    int maxSamplesPerClass = 20000; // in [1, 2^20]
    std::uint32_t seed = 1;
    // How far, in its radii, a mark decides where appearance is unsure (speed/place_vote); 0:
    // appearance alone.
    float placeReach = 3.0F;
    // What the examples' radii are measured in (model::sphereScale of the scan's spacing).
    glm::vec3 sphereScale{1.0F};
    // The features' step in voxels per axis (classifierFeatureStride of the scan's spacing).
    glm::ivec3 featureStride{1};
};

// What the training took and found; seconds of wall time, GPU work finished.
struct ClassifierTraining {
    double featureSeconds = 0.0;  // choosing the sample voxels and gathering their features
    double trainSeconds = 0.0;    // the forest on the CPU
    double evaluateSeconds = 0.0; // the forest at every voxel on the GPU (0 when on demand)
    std::size_t insideSamples = 0;
    std::size_t outsideSamples = 0;
    std::size_t insideCovered = 0; // voxels of the scan the inside examples hold
    std::size_t outsideCovered = 0;
    double outOfBagAccuracy = 0.0; // balanced, on the samples (RandomForest::outOfBagAccuracy)
};

class ClassifierSpeed {
  public:
    // intensity: an R32F 3D texture of `dims` real-unit intensities (the scan, or its smoothed
    // copy), read with texelFetch only. Throws std::invalid_argument with one line for a bad
    // texture, bad parameters, or a class without examples or without a voxel in the scan.
    // recycled: the texture of the classifier speed this one replaces (takeTexture()), written
    // over instead of allocating another: a 256^3 float texture takes 0.12 s to allocate on
    // llvmpipe, most of a retraining after a correction. Ignored unless it is R32F of `dims`.
    // hostScan: the intensity texture's values on the host (the raw scan it was uploaded from),
    // or null. Given, the training samples' features come from the CPU twin
    // (speed/classifier_features_cpu), so that the forest learns the scan's numbers whatever a
    // GPU's gather returns (issue 47); else from the GPU's gather.
    ClassifierSpeed(GLuint intensity, glm::ivec3 dims, std::span<const Example> inside,
                    std::span<const Example> outside, const ClassifierParams& params = {},
                    gpu::Texture recycled = {}, const Volume* hostScan = nullptr);

    // R32F 3D texture of dims(): P(inside) - P(outside) per voxel (on demand: where evaluated).
    [[nodiscard]] GLuint texture() const { return texture_.id(); }
    // Gives the texture up, to the classifier speed that replaces this one; texture() is 0 after.
    [[nodiscard]] gpu::Texture takeTexture() { return std::move(texture_); }
    // The forest for the solver to evaluate on demand; no forest (nodes 0) when the texture was
    // filled everywhere.
    [[nodiscard]] OnDemandForest onDemandForest() const;
    [[nodiscard]] glm::ivec3 dims() const { return dims_; }
    [[nodiscard]] const ClassifierTraining& training() const { return training_; }
    [[nodiscard]] const RandomForest& forest() const { return forest_; }
    [[nodiscard]] const PlaceVote& placeVote() const { return placeVote_; }
    // The forest walked on the GPU over given feature rows (kClassifierFeatureCount floats each,
    // e.g. cpuClassifierFeatures'): each row's look, P(inside) - P(outside) over the trees,
    // without the marks' vote; forest().predict's twin. For the numerics check, which compares
    // it beside the evaluation to tell a wrong walk from wrong features. Throws
    // std::invalid_argument for rows of the wrong length, gpu::GpuNumericsError for a look the
    // GPU left unwritten or not finite.
    [[nodiscard]] std::vector<float> walkOnGpu(std::span<const float> features) const;

  private:
    [[nodiscard]] OnDemandForest gpuForest() const;
    void upload();
    void evaluate(GLuint intensity);
    void clear();

    glm::ivec3 dims_;
    glm::ivec3 stride_;
    int maxDepth_;
    ClassifierEvaluation evaluation_;
    RandomForest forest_;
    ClassifierTraining training_;
    gpu::Buffer nodes_; // forest_ flattened for the GPU (classifier_forest.glsl)
    gpu::Buffer roots_;
    PlaceVote placeVote_;
    gpu::Texture place_; // placeVote_ for the GPU, R16F, linear filtering
    gpu::Texture texture_;
};

// Binds the forest's buffers and the place vote and sets the uniforms of
// speed/classifier_forest.glsl on a program that includes it, for a scan of `dims` (the caller
// binds the intensity at SPEED_SOURCE_UNIT).
void bindClassifierForest(GLuint program, const OnDemandForest& forest, const glm::ivec3& dims);

} // namespace steerseg::speed
