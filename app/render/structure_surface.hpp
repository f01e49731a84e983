#pragma once

// What the 3D view draws of a session's other structures (docs/structures.md): plain values, so
// that the layers above hand them over without naming the renderer's GL types.
#include "core/mask_runs.hpp"

#include <cstddef>
#include <glm/vec3.hpp>

namespace steerseg::render {

// One structure beside the level set: its inside voxels over the scan's linear index (i
// fastest), borrowed for the call that takes it, its colour (r, g, b within 0..1) and whether
// it is shown.
struct StructureSurface {
    const MaskRuns* mask = nullptr;
    glm::vec3 colour{1.0F};
    bool visible = true;
};

// The most layers shown at once: the ray caster's colour table (render/raycast.comp).
inline constexpr std::size_t kMaxStructureSurfaces = 64;

} // namespace steerseg::render
