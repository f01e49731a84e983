#pragma once

#include "render/band_bounds.hpp"
#include "render/view_bindings.hpp"

namespace steerseg::render {

// The 3D view (shaders/render/raycast.comp): owns the program, the baked transfer function and
// the level set's band box for the surface search.
class VolumeView {
  public:
    VolumeView();
    void draw(const RenderInputs& in, const ViewParams& params);

  private:
    void bakeTransfer(const gpu::ScanTexture& scan, const TransferFunction& tf);

    // The ray caster's variants: [with a level set][with the gradient texture].
    PoolProgram programs_[2][2] = {
        {PoolProgram{"render/raycast.comp", {{"HAS_SURFACE", "0"}, {"GRADIENT_TEXTURE", "0"}}},
         PoolProgram{"render/raycast.comp", {{"HAS_SURFACE", "0"}, {"GRADIENT_TEXTURE", "1"}}}},
        {PoolProgram{"render/raycast.comp", {{"HAS_SURFACE", "1"}, {"GRADIENT_TEXTURE", "0"}}},
         PoolProgram{"render/raycast.comp", {{"HAS_SURFACE", "1"}, {"GRADIENT_TEXTURE", "1"}}}}};
    BandBounds bandBounds_;
    gpu::Texture lut_;
    gpu::Texture occupancy_;
    TransferFunction baked_;
    bool haveBaked_ = false;
};

} // namespace steerseg::render
