#pragma once

// The structures that are not being steered, as contours in their colours over the slice views
// (docs/structures.md): the active one is the renderer's yellow contour. Each view's edges are
// found again only when its plane or the structures change, not every frame.
#include "core/mask_slice.hpp"
#include "ui/imgui_layer.hpp"
#include "ui/screen_state.hpp"

#include <array>
#include <cstdint>
#include <vector>

namespace steerseg::ui {

class StructureContours {
  public:
    // Draws over each slice view of `screen` the visible structures of screen.structures but
    // the active one, between ImGuiLayer::beginFrame and endFrame.
    void draw(const ImGuiLayer& layer, const ScreenState& screen, const glm::ivec3& dims);

  private:
    struct Plane {
        std::uint64_t version = 0;
        int axis = -1;
        int index = -1;
        std::vector<std::vector<MaskEdge>> edges; // per structure, in the list's order
    };
    std::array<Plane, 2> planes_; // slice1's, slice2's
};

} // namespace steerseg::ui
