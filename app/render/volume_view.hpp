#pragma once

#include "render/view_bindings.hpp"

namespace steerseg::render {

// The 3D view (shaders/render/raycast.comp): owns the program and the baked transfer function.
class VolumeView {
  public:
    VolumeView();
    void draw(const RenderInputs& in, const ViewParams& params);

  private:
    void bakeTransfer(const gpu::ScanTexture& scan, const TransferFunction& tf);

    PoolProgram program_{"render/raycast.comp"};
    gpu::Texture lut_;
    gpu::Texture occupancy_;
    TransferFunction baked_;
    bool haveBaked_ = false;
};

} // namespace steerseg::render
