#pragma once

#include "render/slice_frame.hpp"
#include "render/view_bindings.hpp"

namespace steerseg::render {

// Axial / coronal / sagittal views (shaders/render/slice.comp).
class SliceView {
  public:
    SliceFrame draw(const RenderInputs& in, const ViewParams& params);

  private:
    PoolProgram program_{"render/slice.comp"};
};

// Glyph index of a side letter in slice.comp's font (A I L P R S), -1 if none.
int glyphIndex(char side);

} // namespace steerseg::render
