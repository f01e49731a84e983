#include "kiosk/view_painter.hpp"

#include "engine/view_setup.hpp"

#include <chrono>
#include <optional>
#include <sstream>
#include <string>

namespace steerseg::kiosk {

namespace {

constexpr std::size_t kVolume = 0;
constexpr std::size_t kFirst = 1;
constexpr std::size_t kSecond = 2;
// The budget's split between the views when all three have work: the 3D view costs the most
// per pixel on every machine.
constexpr std::array<double, 3> kShare{0.6, 0.2, 0.2};

glm::ivec2 rectSize(const ui::Rect& r) {
    return {r.w, r.h};
}

// What a view shows: a change in any of it redraws the view.
std::string volumeSignature(const workflow::Status& s, std::uint64_t version,
                            const glm::ivec2& size) {
    std::ostringstream o;
    o << size.x << 'x' << size.y << ' ' << s.view.yawDeg << ' ' << s.view.pitchDeg << ' '
      << s.view.zoom << ' ' << s.view.transfer << ' ' << s.view.windowLevel << ' '
      << s.view.windowWidth << ' ' << s.hasLevelSet << ' ' << version;
    return o.str();
}

std::string sliceSignature(const workflow::Status& s, std::uint64_t version, const glm::ivec2& size,
                           model::SliceAxis axis, std::optional<std::uint64_t> speedVersion) {
    std::ostringstream o;
    o << size.x << 'x' << size.y << ' ' << static_cast<int>(axis) << ' '
      << s.view.slice[static_cast<int>(axis)] << ' ' << s.view.windowLevel << ' '
      << s.view.windowWidth << ' ' << s.hasLevelSet << ' ' << version;
    if (speedVersion) {
        o << ' ' << s.params.T << ' ' << s.params.eps << ' ' << *speedVersion;
    }
    return o.str();
}

} // namespace

ViewPainter::ViewPainter(double interactiveScale) {
    views_[kVolume].refiner = ViewRefiner(interactiveScale);
    // Slices are cheap everywhere but a software rasteriser: full-size previews where they fit.
    views_[kFirst].refiner = ViewRefiner(1.0);
    views_[kSecond].refiner = ViewRefiner(1.0);
    for (std::size_t n = 0; n < views_.size(); ++n) {
        views_[n].previewTarget = static_cast<int>(n);
        views_[n].fullTarget = static_cast<int>(n) + 3;
    }
}

void ViewPainter::reset() {
    for (View& v : views_) {
        v.refiner.changed();
        v.signature.clear();
        v.shownTarget = -1;
        v.shownFrame.reset();
    }
}

bool ViewPainter::settled() const {
    for (const View& v : views_) {
        if (v.shownTarget < 0 || !v.refiner.fullReady()) {
            return false;
        }
    }
    return true;
}

std::pair<double, double> ViewPainter::takeDrawn() {
    const std::pair<double, double> out{drawnPixels_, drawnSeconds_};
    drawnPixels_ = 0.0;
    drawnSeconds_ = 0.0;
    return out;
}

bool ViewPainter::paintView(View& view, session::Session& session, render::ViewParams params,
                            double seconds, double refineSeconds) {
    const ViewRefiner::Plan plan =
        view.refiner.plan(params.size, view.refiner.dirty() ? seconds : refineSeconds);
    if (plan.kind == ViewRefiner::Plan::Nothing) {
        return false;
    }
    params.size = plan.size;
    if (plan.kind == ViewRefiner::Plan::Preview) {
        params.target = view.previewTarget;
    } else {
        params.target = view.fullTarget;
        params.region = plan.region;
    }
    const auto start = std::chrono::steady_clock::now();
    std::optional<render::SliceFrame> frame = session.render(params);
    // The draw's cost, not the time to queue it: the refiner sizes the next one by it.
    session.finishGpuWork();
    const double spent =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    view.refiner.drawn(plan, spent);
    const glm::ivec2 area =
        plan.kind == ViewRefiner::Plan::Tile ? glm::ivec2(plan.region.z, plan.region.w) : plan.size;
    drawnPixels_ += static_cast<double>(area.x) * area.y;
    drawnSeconds_ += spent;
    // A preview shows at once; the full picture once its last tile is drawn.
    if (plan.kind == ViewRefiner::Plan::Preview || view.refiner.fullReady()) {
        view.shownTarget = params.target;
        view.shownFrame = frame;
        if (params.kind == render::ViewKind::Volume3d) {
            view.shownCamera = params.camera;
        }
        return true;
    }
    return false;
}

bool ViewPainter::draw(session::Session& session, const workflow::Status& status,
                       std::uint64_t levelSetVersion, std::uint64_t speedVersion,
                       const ui::Layout& layout, double seconds, double refineSeconds) {
    const std::array<ui::Rect, 3> rects{layout.view3d, layout.slice1, layout.slice2};
    const std::array<model::SliceAxis, 2> axes{status.view.first, status.view.second};
    std::array<std::optional<render::ViewParams>, 3> params;
    std::array<bool, 3> due{};
    double dueShare = 0.0;
    for (std::size_t n = 0; n < views_.size(); ++n) {
        const glm::ivec2 size = rectSize(rects[n]);
        if (size.x <= 0 || size.y <= 0) {
            continue;
        }
        std::string signature;
        if (n == kVolume) {
            params[n] = engine::volumeViewParams(session, status, size);
            // The other structures it draws too.
            signature = volumeSignature(status, levelSetVersion, size) + ' ' +
                        std::to_string(session.structuresVersion().value_or(0));
        } else {
            const bool speed = n == kSecond;
            const model::SliceAxis axis = axes[n - 1];
            params[n] = engine::sliceViewParams(session, status, axis, speed, size);
            signature = sliceSignature(status, levelSetVersion, size, axis,
                                       speed ? std::optional(speedVersion) : std::nullopt);
        }
        View& view = views_[n];
        if (signature != view.signature) {
            view.signature = signature;
            view.refiner.changed();
        }
        due[n] = view.refiner.dirty() || !view.refiner.fullReady();
        dueShare += due[n] ? kShare[n] : 0.0;
    }
    // The time goes to the views with work, in proportion to their shares: a view that is
    // complete leaves its part to the others' tiles.
    bool changed = false;
    for (std::size_t n = 0; n < views_.size(); ++n) {
        if (params[n] && due[n]) {
            const double part = kShare[n] / dueShare;
            changed =
                paintView(views_[n], session, *params[n], seconds * part, refineSeconds * part) ||
                changed;
        }
    }
    return changed;
}

ui::ScreenState ViewPainter::compose(session::Session& session, const ui::Layout& layout,
                                     ScreenCompositor& screen) const {
    const std::array<ui::Rect, 3> rects{layout.view3d, layout.slice1, layout.slice2};
    ui::ScreenState state;
    state.layout = layout;
    for (std::size_t n = 0; n < views_.size(); ++n) {
        const View& v = views_[n];
        if (v.shownTarget < 0 || rects[n].w <= 0 || rects[n].h <= 0) {
            continue;
        }
        const glm::ivec2 size = session.pictureSize(v.shownTarget);
        screen.drawPicture(session.pictureTexture(v.shownTarget), size, rects[n]);
        if (n == kVolume && v.shownCamera) {
            state.view3d = ui::ScreenState::VolumeView{*v.shownCamera, session.scan().geometry(),
                                                       size, rects[n]};
        }
        if (n != kVolume && v.shownFrame) {
            (n == kFirst ? state.slice1 : state.slice2) =
                ui::SliceView{*v.shownFrame, size, rects[n]};
        }
    }
    return state;
}

} // namespace steerseg::kiosk
