#include "kiosk/view_refiner.hpp"

#include <algorithm>
#include <cmath>

namespace steerseg::kiosk {

namespace {

// A band is at least this many rows: the ray caster works in 8x8 tiles, and a band thinner
// than a tile costs a whole tile's time anyway.
constexpr int kMinBandRows = 8;

} // namespace

ViewRefiner::ViewRefiner(double maxPreviewScale, double minPreviewScale)
    : maxScale_(std::clamp(maxPreviewScale, 1e-3, 1.0)),
      minScale_(std::clamp(minPreviewScale, 1e-3, maxScale_)) {}

void ViewRefiner::changed() {
    dirty_ = true;
    fullReady_ = false;
    nextRow_ = 0;
}

ViewRefiner::Plan ViewRefiner::plan(const glm::ivec2& fullSize, double seconds) {
    Plan p;
    if (fullSize.x <= 0 || fullSize.y <= 0) {
        return p;
    }
    if (fullSize != full_) {
        full_ = fullSize;
        changed();
    }
    const double pixels = static_cast<double>(full_.x) * full_.y;
    seconds = std::max(seconds, 0.0);
    if (dirty_) {
        // Unknown cost: start small, the next frames grow to what fits.
        double scale = minScale_ * 2.0;
        if (secondsPerPixel_ > 0.0) {
            scale = std::sqrt(seconds / (secondsPerPixel_ * pixels));
        }
        scale = std::clamp(scale, minScale_, maxScale_);
        p.kind = Plan::Preview;
        p.size = glm::max(glm::ivec2(glm::round(glm::dvec2(full_) * scale)), glm::ivec2(1));
        return p;
    }
    if (fullReady_) {
        return p;
    }
    int rows = kMinBandRows;
    if (secondsPerPixel_ > 0.0) {
        rows = static_cast<int>(seconds / (secondsPerPixel_ * full_.x));
    }
    rows = std::clamp(rows, kMinBandRows, full_.y - nextRow_);
    p.kind = Plan::Band;
    p.size = full_;
    p.rows = {nextRow_, rows};
    return p;
}

void ViewRefiner::drawn(const Plan& plan, double seconds) {
    if (plan.kind == Plan::Nothing) {
        return;
    }
    const int rows = plan.kind == Plan::Band ? plan.rows.y : plan.size.y;
    const double pixels = static_cast<double>(plan.size.x) * rows;
    if (pixels > 0.0 && std::isfinite(seconds) && seconds >= 0.0) {
        const double sample = seconds / pixels;
        secondsPerPixel_ =
            secondsPerPixel_ <= 0.0 ? sample : 0.7 * secondsPerPixel_ + 0.3 * sample;
    }
    if (plan.kind == Plan::Preview) {
        dirty_ = false;
        previewReady_ = true;
        // A preview at full size is the full picture: nothing left to refine.
        fullReady_ = plan.size == full_;
        nextRow_ = fullReady_ ? full_.y : 0;
        return;
    }
    nextRow_ = plan.rows.x + plan.rows.y;
    fullReady_ = nextRow_ >= full_.y;
}

} // namespace steerseg::kiosk
