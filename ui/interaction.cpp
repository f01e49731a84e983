#include "ui/interaction.hpp"

#include "workflow/transition_table.hpp"

#include <cmath>

namespace steerseg::ui {

namespace {

using model::Action;
using model::ActionKind;
using model::State;

bool scanShown(State s) {
    return s != State::NoScan && s != State::Loading;
}

} // namespace

InteractionConfig interactionConfig(double dpi, double probeRadiusMm) {
    if (!(dpi > 0.0) || !std::isfinite(dpi)) {
        dpi = 96.0;
    }
    InteractionConfig c;
    c.pxPerSlice = 1.5 * dpi / 25.4;
    if (probeRadiusMm > 0.0 && std::isfinite(probeRadiusMm)) {
        c.probeRadiusMm = probeRadiusMm;
    }
    return c;
}

Interaction::Interaction(InteractionConfig config) : config_(config) {}

std::vector<Action> Interaction::onGesture(const Gesture& g, const ScreenState& screen,
                                           const workflow::Status& status) {
    if (!scanShown(status.state)) {
        return {};
    }
    switch (regionAt(screen.layout, g.start.x, g.start.y)) {
    case Region::Slice1:
        if (screen.slice1) {
            return onSlice(g, *screen.slice1, status.view.first, status);
        }
        break;
    case Region::Slice2:
        if (screen.slice2) {
            return onSlice(g, *screen.slice2, status.view.second, status);
        }
        break;
    case Region::View3d:
        return onView3d(g);
    case Region::Panel:
    case Region::None:
        break;
    }
    return {};
}

std::vector<Action> Interaction::page(model::SliceAxis axis, double& accumulated, double amount) {
    accumulated += amount;
    const double whole = std::trunc(accumulated);
    if (whole == 0.0) {
        return {};
    }
    accumulated -= whole;
    return {model::PageSlice{axis, static_cast<int>(whole)}};
}

std::vector<Action> Interaction::onSlice(const Gesture& g, const SliceView& view,
                                         model::SliceAxis axis, const workflow::Status& status) {
    switch (g.kind) {
    case Gesture::Kind::Tap:
    case Gesture::Kind::LongPress: {
        const std::optional<glm::dvec3> voxel = voxelAtScreen(view, g.position);
        if (!voxel || !insideScan(*voxel, status.scan.dims)) {
            return {};
        }
        // What a touch may mean follows the workflow's table for the state; its guards (a
        // level set to erase from, say) are the workflow's to check and explain.
        const model::ActionKinds offered = workflow::offeredActions(status.state);
        // Outside mode: a tap is a counter-example for the classify speed.
        if (status.outsideMode && g.kind == Gesture::Kind::Tap &&
            offered.contains(ActionKind::MarkOutside)) {
            return {model::MarkOutside{*voxel, config_.probeRadiusMm}};
        }
        // Before the first seed a tap looks at the tissue; after it, it places spheres.
        if (status.state == State::Inspect && g.kind == Gesture::Kind::Tap) {
            return {model::Probe{*voxel, config_.probeRadiusMm}};
        }
        if (g.kind == Gesture::Kind::LongPress || status.eraseMode) {
            if (offered.contains(ActionKind::Erase)) {
                return {model::Erase{*voxel, 0.0}};
            }
            return {};
        }
        if (offered.contains(ActionKind::AddSeed)) {
            return {model::AddSeed{*voxel, 0.0}};
        }
        return {};
    }
    case Gesture::Kind::Drag:
        if (g.id != dragId_) {
            dragId_ = g.id;
            dragSlices_ = 0.0;
        }
        // Dragging up goes up through the slices, like pushing a stack of films away.
        return page(axis, dragSlices_, -g.delta.y / config_.pxPerSlice);
    case Gesture::Kind::Wheel:
        return page(axis, wheelSlices_, g.wheel);
    case Gesture::Kind::Pinch:
        break;
    }
    return {};
}

std::vector<Action> Interaction::onView3d(const Gesture& g) {
    switch (g.kind) {
    case Gesture::Kind::Drag:
        if (g.delta.x == 0.0 && g.delta.y == 0.0) {
            return {};
        }
        return {
            model::RotateView{g.delta.x * config_.degreesPerPx, g.delta.y * config_.degreesPerPx}};
    case Gesture::Kind::Pinch:
        if (!(g.scale > 0.0) || !std::isfinite(g.scale) || g.scale == 1.0) {
            return {};
        }
        return {model::ZoomView{g.scale}};
    case Gesture::Kind::Wheel:
        return {model::ZoomView{std::pow(config_.zoomPerDetent, g.wheel)}};
    case Gesture::Kind::Tap:
    case Gesture::Kind::LongPress:
        break;
    }
    return {};
}

} // namespace steerseg::ui
