#pragma once

// The caption in the corner of each view: "3D", "Axial  slice 41/80", "Coronal — speed  12/80".
#include "model/action.hpp"
#include "ui/slice_mapping.hpp"

#include <glm/glm.hpp>
#include <string>

namespace steerseg::ui {

std::string axisLabel(model::SliceAxis axis);

// `dims`: the scan's; the slice number is 1-based of the frame's slice axis.
std::string view3dCaption();
std::string contourCaption(model::SliceAxis axis, const render::SliceFrame& frame,
                           const glm::ivec3& dims);
std::string speedCaption(model::SliceAxis axis, const render::SliceFrame& frame,
                         const glm::ivec3& dims);

} // namespace steerseg::ui
