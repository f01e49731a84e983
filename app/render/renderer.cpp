#include "render/renderer.hpp"

#include "gpu/gl_state_guard.hpp"

#include <stdexcept>
#include <string>

namespace steerseg::render {

glm::dvec3 volumeCentre(const Geometry& g) {
    return g.indexToWorld(0.5 * (glm::dvec3(g.dims) - 1.0));
}

double volumeExtentMm(const Geometry& g) {
    return glm::length(glm::dvec3(g.dims) * g.spacing);
}

namespace {

gpu::Buffer makeEmptyBuffer() {
    gpu::GlStateGuard guard;
    const float zero[4] = {0.0F, 0.0F, 0.0F, 0.0F};
    return gpu::createBuffer(GL_SHADER_STORAGE_BUFFER, sizeof(zero), zero, GL_STATIC_DRAW);
}

} // namespace

Renderer::Renderer(const Volume& scan, const gpu::ScanTexture& texture, std::size_t gradientBudget)
    : geometry_(scan.geometry()), stats_(scan.stats()), scan_(&texture), skip_(scan, texture),
      labels_(scan.dims(), skip_.blockSize()), gradient_(texture, gradientBudget),
      empty_(makeEmptyBuffer()) {
    if (texture.dims() != scan.dims()) {
        throw std::invalid_argument("renderer: the scan texture is not this scan's size");
    }
}

Renderer::Renderer(const Volume& scan, std::size_t gradientBudget)
    : geometry_(scan.geometry()), stats_(scan.stats()),
      ownScan_(std::make_unique<gpu::ScanTexture>(scan)), scan_(ownScan_.get()),
      skip_(scan, *scan_), labels_(scan.dims(), skip_.blockSize()),
      gradient_(*scan_, gradientBudget), empty_(makeEmptyBuffer()) {}

void Renderer::setStructures(std::span<const StructureSurface> layers, std::uint64_t version) {
    gpu::GlStateGuard guard;
    labels_.set(layers, version);
}

std::optional<SliceFrame> Renderer::render(const ViewParams& params,
                                           const solver::BrickPoolView* pool,
                                           const speed::SpeedInputs& speed) {
    if (params.target < 0 || params.target >= kRenderTargets) {
        throw std::invalid_argument("render target " + std::to_string(params.target) +
                                    " is not 0.." + std::to_string(kRenderTargets - 1));
    }
    gpu::GlStateGuard guard;
    last_ = static_cast<std::size_t>(params.target);
    RenderTarget& target = targets_[last_];
    target.ensureSize(params.size);
    const RenderInputs in{*scan_,      skip_,  geometry_,           pool,
                          empty_.id(), target, gradient_.texture(), speed};
    if (params.kind == ViewKind::Volume3d) {
        volume_.draw(in, params, labels_);
        return std::nullopt;
    }
    return slices_.draw(in, params);
}

const RenderTarget& Renderer::target(int index) const {
    if (index < 0 || index >= kRenderTargets) {
        throw std::invalid_argument("render target " + std::to_string(index) + " is not 0.." +
                                    std::to_string(kRenderTargets - 1));
    }
    return targets_[static_cast<std::size_t>(index)];
}

ViewParams Renderer::defaultParams(ViewKind kind, const glm::ivec2& size) const {
    ViewParams p;
    p.kind = kind;
    p.size = size;
    p.camera =
        Camera::preset(CameraPreset::Anterior, volumeCentre(geometry_), volumeExtentMm(geometry_));
    p.transfer = transferPreset(TfPreset::Mr, stats_);
    p.window = windowPreset(TfPreset::Mr, stats_);
    return p;
}

} // namespace steerseg::render
