#pragma once

#include "render/band_bounds.hpp"
#include "render/structure_labels.hpp"
#include "render/view_bindings.hpp"

#include <cstddef>
#include <cstdint>
#include <vector>

namespace steerseg::render {

// The 3D view (shaders/render/raycast.comp): owns the programs, the baked transfer function with
// the blocks it leaves empty, the level set's band box for the surface search and the list of
// pixels whose ray hit the surface. Draws the other structures in `labels` beside the level set.
class VolumeView {
  public:
    VolumeView();
    void draw(const RenderInputs& in, const ViewParams& params, const StructureLabels& labels);

  private:
    void bakeTransfer(const gpu::ScanTexture& scan, const SkipGrid& skip,
                      const TransferFunction& tf);
    // The skipping texture: the transfer function's visible blocks and the labelled ones,
    // uploaded when either changed.
    void updateSkipTexture(const SkipGrid& skip, const StructureLabels& labels);
    // Makes `program` current with the view's textures and uniforms.
    void use(GLuint program, const RenderInputs& in, const ViewParams& params,
             const StructureLabels* labels);
    static PoolProgram variant(int surface, int gradient, int labels, int surfacePass = 0);

    // The surface hits buffer (render/raycast.comp's SurfaceHits): the indirect dispatch and
    // the count, then one uvec4 per hit.
    static constexpr std::size_t kHitsHeader = 16;
    static constexpr std::size_t kHitBytes = 16;

    // The ray caster's variants: [with a level set][with the gradient texture][with other
    // structures]. Each is built when first drawn.
    PoolProgram programs_[2][2][2] = {
        {{variant(0, 0, 0), variant(0, 0, 1)}, {variant(0, 1, 0), variant(0, 1, 1)}},
        {{variant(1, 0, 0), variant(1, 0, 1)}, {variant(1, 1, 0), variant(1, 1, 1)}}};
    // The second pass over the pixels whose ray hit an opaque surface: [with the gradient
    // texture]. The first pass lists no ray that ended at another structure.
    PoolProgram surfacePass_[2] = {variant(1, 0, 0, 1), variant(1, 1, 0, 1)};
    gpu::Buffer hits_;
    std::size_t hitCapacity_ = 0;
    BandBounds bandBounds_;
    gpu::Texture lut_;
    gpu::Texture occupancy_;
    // RG8 per skipping block: may hold a visible sample (SkipGrid), holds a label
    // (StructureLabels::blocks()).
    gpu::Texture visibleBlocks_;
    std::vector<std::uint8_t> tfVisible_; // SkipGrid::visibleBlocks of the baked function
    bool skipStale_ = true;               // tfVisible_ changed since the texture's upload
    std::uint64_t labelsMerged_ = 0;      // StructureLabels::uploads() in the texture
    TransferFunction baked_;
    bool haveBaked_ = false;
};

} // namespace steerseg::render
