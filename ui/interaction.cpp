#include "ui/interaction.hpp"

#include "workflow/transition_table.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace steerseg::ui {

namespace {

using model::Action;
using model::ActionKind;
using model::State;

bool scanShown(State s) {
    return s != State::NoScan && s != State::Loading;
}

// What a one-finger drag paints in: what a tap would place (its sphere along the path), or
// nothing where a tap places none (inspect's probe, review), and the drag pages.
std::optional<model::StrokeMode> paintMode(const workflow::Status& status) {
    const model::ActionKinds offered = workflow::offeredActions(status.state);
    if (!offered.contains(ActionKind::PaintStroke)) {
        return std::nullopt;
    }
    if (status.outsideMode && offered.contains(ActionKind::MarkOutside)) {
        return model::StrokeMode::Outside;
    }
    if (status.state == State::Inspect) {
        return std::nullopt;
    }
    if (status.eraseMode) {
        return offered.contains(ActionKind::Erase) ? std::optional(model::StrokeMode::Erase)
                                                   : std::nullopt;
    }
    return offered.contains(ActionKind::AddSeed) ? std::optional(model::StrokeMode::Add)
                                                 : std::nullopt;
}

// Box mode applies where the table lets a box be set (inspect and steering).
bool boxMode(const workflow::Status& status) {
    return status.boxMode && workflow::offeredActions(status.state).contains(ActionKind::SetBox);
}

// The face whose edge on the screen lies within `tolerance` pixels of `p` (the nearest), where
// the view's slice cuts `box`.
std::optional<model::BoxFace> faceAt(const SliceView& view, const model::Box& box,
                                     const glm::dvec2& p, double tolerance) {
    const std::optional<ScreenBox> r = boxOnScreen(view, box);
    if (!r) {
        return std::nullopt;
    }
    const render::SliceFrame& f = view.frame;
    std::optional<model::BoxFace> best;
    double nearest = tolerance;
    // Screen axis 0 (x) shows index axis u, screen axis 1 (y) index axis v.
    for (const int s : {0, 1}) {
        const int axis = s == 0 ? f.axisU : f.axisV;
        const int across = 1 - s;
        if (p[across] < r->min[across] - tolerance || p[across] > r->max[across] + tolerance) {
            continue; // beside the edge's span
        }
        for (const bool high : {false, true}) {
            glm::dvec3 edge(f.slice);
            edge[axis] = high ? box.hi[axis] + 0.5 : box.lo[axis] - 0.5;
            const double d = std::abs(p[s] - screenOfVoxel(view, edge)[s]);
            if (d <= nearest) {
                nearest = d;
                best = model::BoxFace{axis, high};
            }
        }
    }
    return best;
}

// The box a drag from `from` to `to` (voxels, within the scan) on `view` draws: its rectangle
// on the view's two axes; across them the box's extent before, or for a first box the smaller
// drawn side in mm, centred on the view's slice.
model::Box drawnBox(const render::SliceFrame& f, const glm::dvec3& from, const glm::dvec3& to,
                    const std::optional<model::Box>& before, const workflow::ScanInfo& scan) {
    const glm::ivec3 dims = scan.dims;
    model::Box b = before.value_or(model::Box{});
    double sideMm = std::numeric_limits<double>::infinity();
    for (const int a : {f.axisU, f.axisV}) {
        b.lo[a] =
            std::clamp(static_cast<int>(std::lround(std::min(from[a], to[a]))), 0, dims[a] - 1);
        b.hi[a] = std::clamp(static_cast<int>(std::lround(std::max(from[a], to[a]))), b.lo[a],
                             dims[a] - 1);
        sideMm = std::min(sideMm, (b.hi[a] - b.lo[a] + 1) * scan.spacing[a]);
    }
    if (!before) {
        const int w = f.sliceAxis;
        const double spacing = scan.spacing[w] > 0.0 ? scan.spacing[w] : 1.0;
        const double half = 0.5 * (std::max(sideMm / spacing, 1.0) - 1.0);
        b.lo[w] = std::clamp(static_cast<int>(std::lround(f.slice - half)), 0, dims[w] - 1);
        b.hi[w] = std::clamp(static_cast<int>(std::lround(f.slice + half)), b.lo[w], dims[w] - 1);
    }
    return b;
}

// Successive points closer than this (voxels) add nothing: a finger at rest, or moving within
// one voxel, sends one point.
constexpr double kMinPointStep = 0.5;

} // namespace

InteractionConfig interactionConfig(double dpi, double probeRadiusMm) {
    if (!(dpi > 0.0) || !std::isfinite(dpi)) {
        dpi = 96.0;
    }
    InteractionConfig c;
    c.pxPerSlice = 1.5 * dpi / 25.4;
    // Finer than the touch target: an edge must be found within a finger's width, but a drag
    // begun well inside the box draws a new extent.
    c.boxEdgePx = 2.0 * dpi / 25.4;
    if (probeRadiusMm > 0.0 && std::isfinite(probeRadiusMm)) {
        c.probeRadiusMm = probeRadiusMm;
    }
    return c;
}

Interaction::Interaction(InteractionConfig config) : config_(config) {}

std::vector<Action> Interaction::onGesture(const Gesture& g, const ScreenState& screen,
                                           const workflow::Status& status) {
    if (stroke_ && g.id != stroke_->id) {
        // Another gesture began before the stroke's finger lifted (a second finger made it a
        // pinch): the operator meant something else, and nothing is painted.
        stroke_.reset();
    }
    if (boxDrag_ && g.id != boxDrag_->id) {
        boxDrag_.reset(); // as a stroke: a second finger means something else
    }
    if (!scanShown(status.state)) {
        stroke_.reset();
        boxDrag_.reset();
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
        if (boxMode(status)) {
            return {}; // box mode: only a drag means something, so a touch changes nothing
        }
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
            if (boxMode(status)) {
                beginBox(g, view, status);
            } else if (const std::optional<model::StrokeMode> mode = paintMode(status)) {
                stroke_ = Stroke{g.id, *mode, {}, {}};
                // The stroke begins where the finger went down, not where it left the slop.
                Gesture down = g;
                down.position = g.start;
                paint(down, view, status);
            }
        }
        if (boxDrag_) {
            return dragBox(g, view, status);
        }
        if (stroke_) {
            return paint(g, view, status);
        }
        // Dragging up goes up through the slices, like pushing a stack of films away.
        return page(axis, dragSlices_, -g.delta.y / config_.pxPerSlice);
    case Gesture::Kind::Wheel:
        return page(axis, wheelSlices_, g.wheel);
    case Gesture::Kind::Pinch:
        // Two fingers dragging together page, whatever a one-finger drag does.
        if (g.id != pinchId_) {
            pinchId_ = g.id;
            pinchSlices_ = 0.0;
        }
        return page(axis, pinchSlices_, -g.delta.y / config_.pxPerSlice);
    }
    return {};
}

std::vector<Action> Interaction::paint(const Gesture& g, const SliceView& view,
                                       const workflow::Status& status) {
    Stroke& s = *stroke_;
    const std::optional<glm::dvec3> voxel = voxelAtScreen(view, g.position);
    // Beside the scan the brush lifts; the path goes on where the finger comes back. Within the
    // scan's outer half voxel the point moves onto the nearest voxel centre the workflow takes.
    if (voxel && insideScan(*voxel, status.scan.dims)) {
        const glm::dvec3 p = glm::clamp(*voxel, glm::dvec3(0.0), glm::dvec3(status.scan.dims - 1));
        if (s.points.empty() || glm::length(p - s.points.back()) >= kMinPointStep) {
            s.points.push_back(p);
            s.screen.push_back(g.position);
        }
    }
    std::vector<Action> out;
    if (g.lifted || s.points.size() >= model::kMaxStrokePoints) {
        if (!s.points.empty()) {
            out.emplace_back(model::PaintStroke{s.mode, s.points, 0.0});
        }
        if (g.lifted) {
            stroke_.reset();
        } else {
            // A scribble longer than one stroke goes on as the next, from where this one ended.
            s.points = {s.points.back()};
            s.screen = {s.screen.back()};
        }
    }
    return out;
}

void Interaction::beginBox(const Gesture& g, const SliceView& view,
                           const workflow::Status& status) {
    const std::optional<glm::dvec3> at = voxelAtScreen(view, g.start);
    const glm::ivec3 dims = status.scan.dims;
    if (!at || dims.x < 1 || dims.y < 1 || dims.z < 1) {
        return;
    }
    BoxDrag d;
    d.id = g.id;
    d.from = glm::clamp(*at, glm::dvec3(0.0), glm::dvec3(dims - 1));
    d.before = status.box;
    if (status.box) {
        d.face = faceAt(view, *status.box, g.start, config_.boxEdgePx);
        d.box = *status.box;
    } else {
        d.box = drawnBox(view.frame, d.from, d.from, std::nullopt, status.scan);
    }
    boxDrag_ = d;
}

std::vector<Action> Interaction::dragBox(const Gesture& g, const SliceView& view,
                                         const workflow::Status& status) {
    BoxDrag& d = *boxDrag_;
    // Beside the view the box stays as the finger last drew it.
    if (const std::optional<glm::dvec3> at = voxelAtScreen(view, g.position)) {
        const glm::dvec3 to = glm::clamp(*at, glm::dvec3(0.0), glm::dvec3(status.scan.dims - 1));
        if (d.face && d.before) {
            // The face moves by the finger's travel, so grabbing it makes no jump.
            const int a = d.face->axis;
            const auto voxels = static_cast<int>(std::lround(to[a] - d.from[a]));
            d.box = model::movedFace(*d.before, *d.face, voxels, status.scan.dims);
        } else {
            d.box = drawnBox(view.frame, d.from, to, d.before, status.scan);
        }
    }
    if (!g.lifted) {
        return {};
    }
    std::vector<Action> out;
    // The face dragged last is the knob's to move (docs/ui.md).
    if (d.face && status.boxFace != d.face) {
        out.emplace_back(model::SetBoxMode{true, d.face});
    }
    if (!status.box || *status.box != d.box) {
        out.emplace_back(model::SetBox{d.box});
    }
    boxDrag_.reset();
    return out;
}

std::optional<model::Box> Interaction::boxDraft() const {
    return boxDrag_ ? std::optional(boxDrag_->box) : std::nullopt;
}

const std::vector<glm::dvec2>& Interaction::strokePath() const {
    static const std::vector<glm::dvec2> kNone;
    return stroke_ ? stroke_->screen : kNone;
}

std::optional<model::StrokeMode> Interaction::strokeMode() const {
    return stroke_ ? std::optional(stroke_->mode) : std::nullopt;
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
