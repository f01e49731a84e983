#pragma once

// Captions over the views ("3D", "Axial  slice 41/80", "Coronal — speed  12/80") and the path
// of a stroke being painted, drawn with ImGui's foreground draw list between
// ImGuiLayer::beginFrame and endFrame.
#include "ui/imgui_layer.hpp"
#include "ui/screen_state.hpp"
#include "workflow/status.hpp"

#include <glm/glm.hpp>
#include <optional>
#include <vector>

namespace steerseg::ui {

void drawViewCaptions(const ImGuiLayer& layer, const ScreenState& screen,
                      const workflow::Status& status);

// The finger's path while a stroke is painted (Interaction::strokePath), in the mode's colour,
// so the operator sees the stroke before it lifts and is applied.
void drawStrokePath(const ImGuiLayer& layer, const std::vector<glm::dvec2>& path,
                    model::StrokeMode mode);

// The operator's box (Status::box) where each slice view's slice cuts it, in amber (the
// contours are yellow, the strokes green, red and blue), and the box a finger is drawing
// (Interaction::boxDraft) over it, lighter and filled, until it lifts.
void drawBoxes(const ImGuiLayer& layer, const ScreenState& screen, const workflow::Status& status,
               const std::optional<model::Box>& draft);

// Review: each visible structure's RECIST pair (Status::measurements) on a slice view that shows
// the axial slice it lies on, in the structure's colour, with its lengths: the long axis solid,
// the perpendicular one thinner.
void drawMeasuredDiameters(const ImGuiLayer& layer, const ScreenState& screen,
                           const workflow::Status& status);

} // namespace steerseg::ui
