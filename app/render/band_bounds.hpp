#pragma once

#include "gpu/gl_handle.hpp"
#include "render/view_bindings.hpp"
#include "solver/brick_pool_view.hpp"

namespace steerseg::render {

// The box of bricks that are not stored as constant outside, computed on the GPU from the
// pool's page table (shaders/render/band_bounds.comp) for the 3D view's surface search, which
// looks for the surface only where a ray crosses that box. Kept in a small SSBO that the ray
// caster reads at VIEW_BAND_BOUNDS_BINDING: no read-back, so it follows the solver every frame.
class BandBounds {
  public:
    BandBounds();
    // Recomputes the box from the pool as it is now and binds the result. The caller holds a
    // gpu::GlStateGuard (the pass changes the program and SSBO bindings).
    void update(const solver::BrickPoolView& pool);

  private:
    PoolProgram program_{"render/band_bounds.comp"};
    gpu::Buffer bounds_;
};

} // namespace steerseg::render
