#pragma once

#include "core/volume.hpp"
#include "gpu/gl_handle.hpp"
#include "gpu/scan_texture.hpp"
#include "render/gradient_texture.hpp"
#include "render/render_params.hpp"
#include "render/render_target.hpp"
#include "render/skip_grid.hpp"
#include "render/slice_view.hpp"
#include "render/structure_labels.hpp"
#include "render/volume_view.hpp"
#include "solver/brick_pool_view.hpp"

#include <array>
#include <cstdint>
#include <memory>
#include <optional>
#include <span>

namespace steerseg::render {

// The renderer of one scan: the scan on the GPU, the 3D view and the slice views, and the
// picture they draw into. Every call saves and restores the GL state it touches
// (gpu::GlStateGuard), so a UI can draw on top in the same context. Needs a current GLES 3.1
// context for its whole life.
class Renderer {
  public:
    // Borrows `texture`, the scan on the GPU (shared with the solver), which must outlive the
    // renderer. `gradientBudget`: bytes the 3D view's gradient texture may take (0: none, the
    // ray caster differences the scan per sample).
    Renderer(const Volume& scan, const gpu::ScanTexture& texture,
             std::size_t gradientBudget = GradientTexture::kDefaultBudget);
    // Uploads and owns the scan's texture (a renderer with no solver beside it).
    explicit Renderer(const Volume& scan,
                      std::size_t gradientBudget = GradientTexture::kDefaultBudget);

    // Draws one view into target(); `pool` is the level set (the solver's poolView(), valid
    // for this call) or null for the scan alone; `speed` what the speed view shows (the solver's
    // speedInputs(), so that it is what moves the front; the default: the threshold speed on the
    // raw scan). Returns the slice frame for slice views.
    std::optional<SliceFrame> render(const ViewParams& params, const solver::BrickPoolView* pool,
                                     const speed::SpeedInputs& speed = {});

    // The picture the last render() drew into, or picture `index` (ViewParams::target).
    [[nodiscard]] const RenderTarget& target() const { return targets_[last_]; }
    [[nodiscard]] const RenderTarget& target(int index) const;
    [[nodiscard]] RgbaImage readback() const { return target().readback(); }
    [[nodiscard]] const Geometry& geometry() const { return geometry_; }
    [[nodiscard]] const gpu::ScanTexture& scan() const { return *scan_; }
    // The session's other structures, which the 3D view draws as opaque surfaces in their
    // colours beside the level set (the visible ones with a surface; the masks are read during
    // this call only). Uploaded only when `version` differs from the last one given;
    // StructureLabels::set says what it refuses.
    void setStructures(std::span<const StructureSurface> layers, std::uint64_t version);
    // The version last given to setStructures (none before the first), and how many times the
    // structures were uploaded.
    [[nodiscard]] std::optional<std::uint64_t> structuresVersion() const {
        return labels_.version();
    }
    [[nodiscard]] std::uint64_t structureUploads() const { return labels_.uploads(); }
    // Whether the 3D view reads a precomputed gradient (false: a scan over its budget).
    [[nodiscard]] bool precomputedGradient() const { return gradient_.available(); }

    // Default parameters for this scan: MR-style presets, anterior camera, middle slice.
    [[nodiscard]] ViewParams defaultParams(ViewKind kind, const glm::ivec2& size) const;

  private:
    Geometry geometry_;
    IntensityStats stats_;
    std::unique_ptr<gpu::ScanTexture> ownScan_;
    const gpu::ScanTexture* scan_;
    SkipGrid skip_;
    StructureLabels labels_;
    GradientTexture gradient_;
    std::array<RenderTarget, kRenderTargets> targets_;
    std::size_t last_ = 0;
    gpu::Buffer empty_;
    VolumeView volume_;
    SliceView slices_;
};

// World position of the volume's centre and the length of its diagonal (camera presets).
glm::dvec3 volumeCentre(const Geometry& g);
double volumeExtentMm(const Geometry& g);

} // namespace steerseg::render
