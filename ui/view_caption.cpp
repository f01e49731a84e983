#include "ui/view_caption.hpp"

namespace steerseg::ui {

namespace {

std::string sliceOf(const render::SliceFrame& f, const glm::ivec3& dims) {
    const int axis = f.sliceAxis >= 0 && f.sliceAxis < 3 ? f.sliceAxis : 2;
    return std::to_string(f.slice + 1) + "/" + std::to_string(dims[axis]);
}

} // namespace

std::string axisLabel(model::SliceAxis axis) {
    switch (axis) {
    case model::SliceAxis::Axial:
        return "Axial";
    case model::SliceAxis::Coronal:
        return "Coronal";
    case model::SliceAxis::Sagittal:
        return "Sagittal";
    }
    return "?";
}

std::string view3dCaption() {
    return "3D";
}

std::string contourCaption(model::SliceAxis axis, const render::SliceFrame& frame,
                           const glm::ivec3& dims) {
    return axisLabel(axis) + "  slice " + sliceOf(frame, dims);
}

std::string speedCaption(model::SliceAxis axis, const render::SliceFrame& frame,
                         const glm::ivec3& dims) {
    return axisLabel(axis) + " \u2014 speed  " + sliceOf(frame, dims);
}

} // namespace steerseg::ui
