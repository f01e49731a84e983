#include "render/renderer.hpp"

#include "render/gl_state_guard.hpp"

namespace steerseg::render {

glm::dvec3 volumeCentre(const Geometry& g) {
    return g.indexToWorld(0.5 * (glm::dvec3(g.dims) - 1.0));
}

double volumeExtentMm(const Geometry& g) {
    return glm::length(glm::dvec3(g.dims) * g.spacing);
}

namespace {

gpu::Buffer makeEmptyBuffer() {
    GlStateGuard guard;
    const float zero[4] = {0.0F, 0.0F, 0.0F, 0.0F};
    return gpu::createBuffer(GL_SHADER_STORAGE_BUFFER, sizeof(zero), zero, GL_STATIC_DRAW);
}

} // namespace

Renderer::Renderer(const Volume& scan, GLuint sharedScan)
    : geometry_(scan.geometry()), stats_(scan.stats()), scan_(scan, sharedScan),
      empty_(makeEmptyBuffer()) {}

std::optional<SliceFrame> Renderer::render(const ViewParams& params, const BrickPoolView* pool) {
    GlStateGuard guard;
    target_.ensureSize(params.size);
    const RenderInputs in{scan_, geometry_, pool, empty_.id(), target_};
    if (params.kind == ViewKind::Volume3d) {
        volume_.draw(in, params);
        return std::nullopt;
    }
    return slices_.draw(in, params);
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
