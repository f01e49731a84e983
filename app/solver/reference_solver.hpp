#pragma once

#include "model/level_set_params.hpp"
#include "model/speed_kind.hpp"

#include <cstdint>
#include <glm/glm.hpp>
#include <limits>
#include <span>
#include <vector>

namespace steerseg::solver {

// The test oracle: a plain dense CPU solver with the GPU solver's discretisation
// (solver/phi_stencil.hpp) and time-step rule. Simple rather than fast.
class ReferenceSolver {
  public:
    // `intensities`: real-unit values, i fastest. Starts with an empty level set (all outside).
    ReferenceSolver(std::vector<float> intensities, const glm::ivec3& dims);

    void setParams(const model::LevelSetParams& params);
    // The GPU solver's setSpeedInputs: `factor` per voxel (i fastest; edge: g, classify:
    // P(in) - P(out)), ignored by the threshold speed. The intensities given to the constructor
    // are the speed's I (pass the smoothed scan to mirror a smoothed GPU run).
    // `withinWindow`: classify bounded by T +- eps (speed::SpeedInputs::withinWindow).
    // std::invalid_argument when the factor's size differs from the volume's.
    void setSpeed(model::SpeedKind kind, std::vector<float> factor, bool withinWindow = false);
    void addSphere(const model::Sphere& sphere);
    void removeSphere(const model::Sphere& sphere);
    void initFromMask(std::span<const std::uint8_t> mask);
    void initFromThreshold(float lo, float hi);

    // Runs up to n iterations, stopping early once the evolved time reaches timeLimit. Returns
    // the iterations performed.
    int step(int n, float timeLimit = std::numeric_limits<float>::infinity());

    [[nodiscard]] int iterations() const { return iterations_; }
    [[nodiscard]] float evolvedTime() const { return time_; }
    [[nodiscard]] int lastSideChangeIteration() const { return lastChange_; }
    [[nodiscard]] const std::vector<float>& phi() const { return phi_; }
    [[nodiscard]] std::vector<std::uint8_t> mask() const;
    [[nodiscard]] const glm::ivec3& dims() const { return dims_; }

  private:
    [[nodiscard]] float at(int i, int j, int k) const;
    // Centre and the six face neighbours (enough for the narrow-band test and up-wind terms).
    [[nodiscard]] struct PhiStencil faceStencil(int i, int j, int k) const;
    [[nodiscard]] struct PhiStencil stencil(int i, int j, int k) const;
    [[nodiscard]] std::size_t index(int i, int j, int k) const;

    [[nodiscard]] float speedAt(std::size_t at) const;

    std::vector<float> intensities_;
    model::SpeedKind speedKind_ = model::SpeedKind::Threshold;
    bool withinWindow_ = false;
    std::vector<float> factor_;
    glm::ivec3 dims_;
    std::vector<float> phi_;
    std::vector<float> next_;
    model::LevelSetParams params_;
    bool haveParams_ = false;
    int iterations_ = 0;
    int lastChange_ = 0;
    float time_ = 0.0F;
};

} // namespace steerseg::solver
