#include "ui/view_caption.hpp"

namespace steerseg::ui {

namespace {

std::string sliceOf(const render::SliceFrame& f, const glm::ivec3& dims) {
    const int axis = f.sliceAxis >= 0 && f.sliceAxis < 3 ? f.sliceAxis : 2;
    return std::to_string(f.slice + 1) + "/" + std::to_string(dims[axis]);
}

} // namespace

std::string axisLabel(workflow::SliceAxis axis) {
    switch (axis) {
    case workflow::SliceAxis::Axial:
        return "Axial";
    case workflow::SliceAxis::Coronal:
        return "Coronal";
    case workflow::SliceAxis::Sagittal:
        return "Sagittal";
    }
    return "?";
}

std::string view3dCaption() {
    return "3D";
}

std::string contourCaption(workflow::SliceAxis axis, const render::SliceFrame& frame,
                           const glm::ivec3& dims) {
    return axisLabel(axis) + "  slice " + sliceOf(frame, dims);
}

std::string speedCaption(workflow::SliceAxis axis, const render::SliceFrame& frame,
                         const glm::ivec3& dims) {
    return axisLabel(axis) + " \u2014 speed  " + sliceOf(frame, dims);
}

} // namespace steerseg::ui
