#include "solver/reference_solver.hpp"

#include "core/volume.hpp"
#include "solver/phi_init.hpp"
#include "solver/phi_stencil.hpp"

#include <algorithm>
#include <stdexcept>
#include <string>
#include <utility>

namespace steerseg::solver {

ReferenceSolver::ReferenceSolver(std::vector<float> intensities, const glm::ivec3& dims)
    : intensities_(std::move(intensities)), dims_(dims) {
    const auto count = static_cast<std::size_t>(dims.x) * static_cast<std::size_t>(dims.y) *
                       static_cast<std::size_t>(dims.z);
    if (dims.x <= 0 || dims.y <= 0 || dims.z <= 0 || intensities_.size() != count) {
        throw std::invalid_argument("reference solver: intensities do not match the dimensions");
    }
    phi_.assign(count, model::kPhiFar);
    next_ = phi_;
}

void ReferenceSolver::setParams(const model::LevelSetParams& params) {
    model::validateParams(params);
    params_ = params;
    haveParams_ = true;
}

void ReferenceSolver::setSpeed(model::SpeedKind kind, std::vector<float> factor,
                               bool withinWindow) {
    if (kind != model::SpeedKind::Threshold && factor.size() != intensities_.size()) {
        throw std::invalid_argument("reference solver: the speed factor has " +
                                    std::to_string(factor.size()) + " voxels, the volume " +
                                    std::to_string(intensities_.size()));
    }
    speedKind_ = kind;
    withinWindow_ = withinWindow && kind == model::SpeedKind::Classify;
    factor_ = std::move(factor);
}

float ReferenceSolver::speedAt(std::size_t at) const {
    const float factor = speedKind_ == model::SpeedKind::Threshold ? 0.0F : factor_[at];
    return dataSpeed(intensities_[at], factor, speedKind_, params_, withinWindow_);
}

void ReferenceSolver::addSphere(const model::Sphere& sphere) {
    model::validateSphere(sphere, dims_);
    applySphere(phi_, dims_, sphere, true);
}

void ReferenceSolver::removeSphere(const model::Sphere& sphere) {
    model::validateSphere(sphere, dims_);
    applySphere(phi_, dims_, sphere, false);
}

void ReferenceSolver::initFromMask(std::span<const std::uint8_t> mask) {
    phi_ = maskToPhi(mask, dims_);
}

void ReferenceSolver::initFromThreshold(float lo, float hi) {
    phi_ = maskToPhi(thresholdMask(intensities_, lo, hi), dims_);
}

std::size_t ReferenceSolver::index(int i, int j, int k) const {
    return linearIndex(dims_, i, j, k);
}

float ReferenceSolver::at(int i, int j, int k) const {
    i = std::clamp(i, 0, dims_.x - 1);
    j = std::clamp(j, 0, dims_.y - 1);
    k = std::clamp(k, 0, dims_.z - 1);
    return phi_[index(i, j, k)];
}

PhiStencil ReferenceSolver::faceStencil(int i, int j, int k) const {
    PhiStencil s;
    s.c = at(i, j, k);
    s.xm = at(i - 1, j, k);
    s.xp = at(i + 1, j, k);
    s.ym = at(i, j - 1, k);
    s.yp = at(i, j + 1, k);
    s.zm = at(i, j, k - 1);
    s.zp = at(i, j, k + 1);
    return s;
}

PhiStencil ReferenceSolver::stencil(int i, int j, int k) const {
    PhiStencil s = faceStencil(i, j, k);
    s.xpyp = at(i + 1, j + 1, k);
    s.xpym = at(i + 1, j - 1, k);
    s.xmyp = at(i - 1, j + 1, k);
    s.xmym = at(i - 1, j - 1, k);
    s.xpzp = at(i + 1, j, k + 1);
    s.xpzm = at(i + 1, j, k - 1);
    s.xmzp = at(i - 1, j, k + 1);
    s.xmzm = at(i - 1, j, k - 1);
    s.ypzp = at(i, j + 1, k + 1);
    s.ypzm = at(i, j + 1, k - 1);
    s.ymzp = at(i, j - 1, k + 1);
    s.ymzm = at(i, j - 1, k - 1);
    return s;
}

int ReferenceSolver::step(int n, float timeLimit) {
    if (!haveParams_) {
        throw std::logic_error("reference solver: setParams before step");
    }
    const model::TimeStepRule rule = model::timeStepRule(params_);
    int done = 0;
    for (; done < n; ++done) {
        // Time step from the fastest data speed on the front (as the GPU's measure pass).
        std::vector<std::size_t> band;
        float maxRate = 0.0F;
        for (int k = 0; k < dims_.z; ++k) {
            for (int j = 0; j < dims_.y; ++j) {
                for (int i = 0; i < dims_.x; ++i) {
                    const PhiStencil s = faceStencil(i, j, k);
                    if (!inNarrowBand(s)) {
                        continue;
                    }
                    band.push_back(index(i, j, k));
                    if (onFront(s)) {
                        const float d = speedAt(band.back());
                        maxRate = std::max(maxRate, std::abs(params_.alpha * d));
                    }
                }
            }
        }
        const float dt = std::min(model::stableTimeStep(rule, maxRate), timeLimit - time_);
        if (!(dt > 0.0F)) {
            break;
        }
        // Voxels off the band keep their clamped value (their rate clamps back to it).
        next_ = phi_;
        bool changed = false;
        for (const std::size_t at : band) {
            const int i = static_cast<int>(at % static_cast<std::size_t>(dims_.x));
            const int j = static_cast<int>((at / static_cast<std::size_t>(dims_.x)) %
                                           static_cast<std::size_t>(dims_.y));
            const int k = static_cast<int>(
                at / (static_cast<std::size_t>(dims_.x) * static_cast<std::size_t>(dims_.y)));
            const PhiStencil s = stencil(i, j, k);
            const float d = speedAt(at);
            const float out = phiStep(s, d, params_.alpha, dt);
            changed = changed || ((out < 0.0F) != (s.c < 0.0F));
            next_[at] = out;
        }
        phi_.swap(next_);
        time_ += dt;
        ++iterations_;
        if (changed) {
            lastChange_ = iterations_;
        }
    }
    return done;
}

std::vector<std::uint8_t> ReferenceSolver::mask() const {
    return insideMask(phi_);
}

} // namespace steerseg::solver
