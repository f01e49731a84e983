#include "kiosk/view_refiner.hpp"

#include <algorithm>
#include <cmath>

namespace steerseg::kiosk {

namespace {

// Tiles are whole 8x8 work groups of the renderer's compute shaders: a thinner tile costs a
// whole group's time anyway.
constexpr int kGroup = 8;
constexpr double kTellingPixels = 4096.0;

int groupsIn(double pixels) {
    return static_cast<int>(std::floor(pixels / kGroup)) * kGroup;
}

} // namespace

ViewRefiner::ViewRefiner(double maxPreviewScale, double minPreviewPixels)
    : maxScale_(std::clamp(maxPreviewScale, 1e-3, 1.0)),
      minPixels_(std::max(minPreviewPixels, 1.0)) {}

void ViewRefiner::changed() {
    dirty_ = true;
    fullReady_ = false;
    cursor_ = glm::ivec2(0);
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
        const double minScale = std::min(maxScale_, std::sqrt(minPixels_ / pixels));
        // Unknown cost: start small; the next frames grow to what fits.
        double scale = minScale;
        if (secondsPerPixel_ > 0.0) {
            scale = std::sqrt(seconds / (secondsPerPixel_ * pixels));
        }
        scale = std::clamp(scale, minScale, maxScale_);
        p.kind = Plan::Preview;
        p.size = glm::max(glm::ivec2(glm::round(glm::dvec2(full_) * scale)), glm::ivec2(1));
        return p;
    }
    if (fullReady_) {
        return p;
    }
    const double budget = secondsPerPixel_ > 0.0 ? seconds / secondsPerPixel_ : 0.0; // pixels
    p.kind = Plan::Tile;
    p.size = full_;
    const int left = full_.y - cursor_.y;
    if (cursor_.x == 0 && budget >= static_cast<double>(full_.x) * kGroup) {
        const int rows = std::clamp(groupsIn(budget / full_.x), kGroup, left);
        p.region = {0, cursor_.y, full_.x, rows};
    } else {
        const int width = std::clamp(groupsIn(budget / kGroup), kGroup, full_.x - cursor_.x);
        p.region = {cursor_.x, cursor_.y, width, std::min(kGroup, left)};
    }
    return p;
}

void ViewRefiner::drawn(const Plan& plan, double seconds) {
    if (plan.kind == Plan::Nothing) {
        return;
    }
    const glm::ivec2 drawnSize =
        plan.kind == Plan::Tile ? glm::ivec2(plan.region.z, plan.region.w) : plan.size;
    const double pixels = static_cast<double>(drawnSize.x) * drawnSize.y;
    // A tiny draw is mostly the dispatch's fixed cost: it cannot say the next, larger one
    // costs more per pixel, once there is an estimate. The estimate rises at once with a slow
    // draw (a tile through the head after one through air) and falls by at most half per draw,
    // so the next tile overruns its time by at most twice. Any draw may lower it: its fixed
    // cost only makes it look dearer. (Only rising with large draws and falling slowly, a
    // first preview that paid for compiling the shader left the tiles at 8x8 pixels for good:
    // the refinement ran at a twentieth of the renderer's speed.)
    const bool telling = pixels >= kTellingPixels || secondsPerPixel_ <= 0.0;
    if (pixels > 0.0 && std::isfinite(seconds) && seconds >= 0.0) {
        const double sample = seconds / pixels;
        if (sample > secondsPerPixel_) {
            secondsPerPixel_ = telling ? sample : secondsPerPixel_;
        } else {
            secondsPerPixel_ = std::max(sample, 0.5 * secondsPerPixel_);
        }
    }
    if (plan.kind == Plan::Preview) {
        dirty_ = false;
        previewReady_ = true;
        // A preview at full size is the full picture: nothing left to refine.
        fullReady_ = plan.size == full_;
        cursor_ = glm::ivec2(0);
        return;
    }
    cursor_.x = plan.region.x + plan.region.z;
    if (cursor_.x >= full_.x) {
        cursor_ = {0, plan.region.y + plan.region.w};
    }
    fullReady_ = cursor_.y >= full_.y;
}

} // namespace steerseg::kiosk
