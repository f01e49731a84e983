// The view state: the 3D camera, the slice views and the display window. It belongs to the
// workflow so scripts and the audit log see it and a replay draws the same frames.
#include "workflow/workflow.hpp"

#include <algorithm>
#include <cmath>

namespace steerseg::workflow {

namespace {

constexpr double kMinZoom = 0.1;
constexpr double kMaxZoom = 10.0;
constexpr double kMaxPitch = 90.0;

bool validAxis(model::SliceAxis a) {
    return static_cast<unsigned>(a) < 3U;
}

} // namespace

Workflow::Outcome Workflow::on(const model::RotateView& a) {
    if (!std::isfinite(a.yaw) || !std::isfinite(a.pitch)) {
        return no("a rotation needs finite angles");
    }
    // Yaw goes round and round; pitch stops at the poles (over the top the picture flips).
    const double yaw = std::remainder(status_.view.yawDeg + a.yaw, 360.0);
    status_.view.yawDeg = yaw == 180.0 ? -180.0 : yaw;
    status_.view.pitchDeg = std::clamp(status_.view.pitchDeg + a.pitch, -kMaxPitch, kMaxPitch);
    return ok();
}

Workflow::Outcome Workflow::on(const model::ZoomView& a) {
    if (!std::isfinite(a.factor) || a.factor <= 0.0) {
        return no("a zoom needs a finite factor > 0");
    }
    status_.view.zoom = std::clamp(status_.view.zoom * a.factor, kMinZoom, kMaxZoom);
    return ok();
}

Workflow::Outcome Workflow::on(const model::PageSlice& a) {
    if (!validAxis(a.axis)) {
        return no("unknown slice orientation");
    }
    const auto i = static_cast<glm::length_t>(a.axis);
    const int count = status_.scan.sliceCount[i];
    const int now = status_.view.slice[i] < 0 ? count / 2 : status_.view.slice[i];
    const long long next = static_cast<long long>(now) + a.delta;
    status_.view.slice[i] = static_cast<int>(std::clamp<long long>(next, 0, count - 1));
    return ok();
}

Workflow::Outcome Workflow::on(const model::SetSlice& a) {
    if (!validAxis(a.axis)) {
        return no("unknown slice orientation");
    }
    const auto i = static_cast<glm::length_t>(a.axis);
    status_.view.slice[i] = std::clamp(a.index, 0, status_.scan.sliceCount[i] - 1);
    return ok();
}

Workflow::Outcome Workflow::on(const model::ShowSlices& a) {
    if (!validAxis(a.first) || !validAxis(a.second)) {
        return no("unknown slice orientation");
    }
    if (a.first == a.second) {
        return no("the two slice views need two different orientations");
    }
    status_.view.first = a.first;
    status_.view.second = a.second;
    return ok();
}

Workflow::Outcome Workflow::on(const model::SetWindow& a) {
    if (!std::isfinite(a.level) || !std::isfinite(a.width) || a.width <= 0.0) {
        return no("a window needs a finite level and a finite width > 0");
    }
    status_.view.windowLevel = a.level;
    status_.view.windowWidth = a.width;
    return ok();
}

} // namespace steerseg::workflow
