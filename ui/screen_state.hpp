#pragma once

// The screen as the kiosk drew it this frame: where each part went and, for the slice views,
// which frame each image shows (what a tap maps through and what the captions name).
#include "core/volume.hpp"
#include "render/camera.hpp"
#include "ui/layout.hpp"
#include "ui/slice_mapping.hpp"
#include "workflow/structures.hpp"

#include <cstdint>
#include <optional>

namespace steerseg::ui {

struct ScreenState {
    Layout layout;
    std::optional<SliceView> slice1; // absent: not drawn (no scan)
    std::optional<SliceView> slice2;
    // The 3D view's picture: its camera and the scan's geometry, so that what the UI draws over
    // it (the box's wire frame) lines up with what the ray caster drew; absent: not drawn.
    struct VolumeView {
        render::Camera camera;
        Geometry geometry;
        glm::ivec2 renderSize{0}; // the picture the camera drew
        Rect rect;                // where it is shown
    };
    std::optional<VolumeView> view3d;
    // The session's structures (Workflow::structureList), the ones not steered drawn as
    // contours; null: none. Their version tells when what was drawn of them is stale.
    const workflow::StructureList* structures = nullptr;
    std::uint64_t structuresVersion = 0;
};

} // namespace steerseg::ui
