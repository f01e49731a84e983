#pragma once

// Captions over the views ("3D", "Axial  slice 41/80", "Coronal — speed  12/80"), drawn with
// ImGui's foreground draw list between ImGuiLayer::beginFrame and endFrame.
#include "ui/imgui_layer.hpp"
#include "ui/screen_state.hpp"
#include "workflow/status.hpp"

namespace steerseg::ui {

void drawViewCaptions(const ImGuiLayer& layer, const ScreenState& screen,
                      const workflow::Status& status);

} // namespace steerseg::ui
