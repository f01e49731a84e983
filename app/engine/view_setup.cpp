#include "engine/view_setup.hpp"

#include "render/slice_frame.hpp"

#include <algorithm>

namespace steerseg::engine {

namespace {

void applyWindow(render::ViewParams& p, const workflow::ViewState& view) {
    if (view.windowWidth > 0.0) { // 0: not set, the scan's default stays
        p.window = {view.windowLevel, view.windowWidth};
    }
}

} // namespace

render::ViewKind viewKindOf(model::SliceAxis axis) {
    switch (axis) {
    case model::SliceAxis::Axial:
        return render::ViewKind::Axial;
    case model::SliceAxis::Coronal:
        return render::ViewKind::Coronal;
    case model::SliceAxis::Sagittal:
        return render::ViewKind::Sagittal;
    }
    return render::ViewKind::Axial;
}

render::ViewParams volumeViewParams(const session::Session& session, const workflow::Status& status,
                                    const glm::ivec2& size) {
    render::ViewParams p = session.defaultView(render::ViewKind::Volume3d, size);
    const workflow::ViewState& view = status.view;
    p.camera.orbit(view.yawDeg, view.pitchDeg);
    if (view.zoom > 0.0) {
        p.camera.zoom(view.zoom);
    }
    if (!view.transfer.empty()) {
        try {
            p.transfer = render::transferPreset(render::parseTfPreset(view.transfer),
                                                session.scan().stats());
        } catch (const std::exception&) {
            // An unknown name keeps the scan's default; the config check already said so.
        }
    }
    applyWindow(p, view);
    p.surface = status.hasLevelSet ? render::SurfaceMode::Opaque : render::SurfaceMode::Hidden;
    // The kiosk's level set is the solver's, moved by the speed in force (a resumed one too:
    // the autosave keeps the speed that drew it).
    p.speed = {static_cast<double>(status.params.T), static_cast<double>(status.params.eps), true};
    return p;
}

render::ViewParams sliceViewParams(const session::Session& session, const workflow::Status& status,
                                   model::SliceAxis axis, bool speed, const glm::ivec2& size) {
    render::ViewParams p = session.defaultView(viewKindOf(axis), size);
    const int index = status.view.slice[static_cast<int>(axis)];
    if (index >= 0) {
        // The workflow pages along the scan's dims; an oblique or permuted scan may step a
        // different index axis for this orientation, so the index is kept in that axis' range.
        const Geometry& g = session.scan().geometry();
        const int along = g.dims[render::sliceAxisFor(g, p.kind)];
        p.slice = std::clamp(index, 0, along - 1);
    }
    applyWindow(p, status.view);
    p.content = speed ? render::SliceContent::Speed : render::SliceContent::Scan;
    p.speed = {static_cast<double>(status.params.T), static_cast<double>(status.params.eps)};
    p.contour = status.hasLevelSet;
    return p;
}

} // namespace steerseg::engine
