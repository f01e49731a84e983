#include "ui/slice_mapping.hpp"

#include <cmath>

namespace steerseg::ui {

namespace {

bool usable(const SliceView& v) {
    return !v.rect.empty() && v.renderSize.x > 0 && v.renderSize.y > 0;
}

// Image pixel index (continuous, pixel centres integers) of a logical screen point.
glm::dvec2 imagePixel(const SliceView& v, const glm::dvec2& p) {
    const glm::dvec2 scale = glm::dvec2(v.renderSize) / glm::dvec2(v.rect.w, v.rect.h);
    return (p - glm::dvec2(v.rect.x, v.rect.y)) * scale - 0.5;
}

} // namespace

std::optional<glm::dvec3> voxelAtScreen(const SliceView& view, const glm::dvec2& p) {
    if (!usable(view) || !std::isfinite(p.x) || !std::isfinite(p.y) ||
        !view.rect.contains(p.x, p.y)) {
        return std::nullopt;
    }
    const glm::dvec2 image = imagePixel(view, p);
    const render::SliceFrame& f = view.frame;
    return f.origin + image.x * f.stepRight + image.y * f.stepDown;
}

glm::dvec2 screenOfVoxel(const SliceView& view, const glm::dvec3& voxel) {
    const render::SliceFrame& f = view.frame;
    const glm::dvec3 d = voxel - f.origin;
    // stepRight and stepDown each move along one index axis (axisU, axisV).
    const double x = d[f.axisU] / f.stepRight[f.axisU];
    const double y = d[f.axisV] / f.stepDown[f.axisV];
    const glm::dvec2 scale = glm::dvec2(view.rect.w, view.rect.h) / glm::dvec2(view.renderSize);
    return glm::dvec2(view.rect.x, view.rect.y) + (glm::dvec2(x, y) + 0.5) * scale;
}

std::optional<ScreenBox> boxOnScreen(const SliceView& view, const model::Box& box) {
    const render::SliceFrame& f = view.frame;
    if (!usable(view) || f.slice < box.lo[f.sliceAxis] || f.slice > box.hi[f.sliceAxis]) {
        return std::nullopt;
    }
    glm::dvec3 lo(f.slice);
    glm::dvec3 hi(f.slice);
    for (const int a : {f.axisU, f.axisV}) {
        lo[a] = box.lo[a] - 0.5;
        hi[a] = box.hi[a] + 0.5;
    }
    // A flipped axis (stepRight or stepDown negative) puts lo right of or below hi.
    const glm::dvec2 p = screenOfVoxel(view, lo);
    const glm::dvec2 q = screenOfVoxel(view, hi);
    return ScreenBox{glm::min(p, q), glm::max(p, q)};
}

bool insideScan(const glm::dvec3& voxel, const glm::ivec3& dims) {
    for (int a = 0; a < 3; ++a) {
        if (!std::isfinite(voxel[a]) || voxel[a] < -0.5 || voxel[a] > dims[a] - 0.5) {
            return false;
        }
    }
    return true;
}

} // namespace steerseg::ui
