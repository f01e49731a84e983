// The kiosk's screen passes: the views and the panel composed and presented within the frame's
// budget, and the frames a script asked for, saved once complete.
#include "exports/image_file.hpp"
#include "gpu/gl_counts.hpp"
#include "kiosk/kiosk.hpp"
#include "render/structure_surface.hpp"

#include <algorithm>
#include <utility>
#include <vector>

namespace steerseg::kiosk {

namespace {

// The structures but the active one (the level set) to the session's 3D view, when `version`
// is not the one it holds (a new session holds none).
void handStructures(session::Session& session, const workflow::StructureList& list,
                    std::uint64_t version) {
    if (session.structuresVersion() == version) {
        return;
    }
    const std::size_t voxels = session.scan().geometry().voxelCount();
    std::vector<render::StructureSurface> others;
    for (std::size_t n = 0; n < list.items.size(); ++n) {
        const workflow::Structure& s = list.items[n];
        if (n == list.active) {
            continue;
        }
        if (!s.mask.runs.empty() && s.mask.voxels != voxels) {
            return; // the previous scan's list, until the workflow starts this scan's
        }
        others.push_back({&s.mask, glm::vec3(s.info.colour), s.info.visible});
    }
    session.setStructures(others, version);
}

} // namespace

void Kiosk::drawScreen(bool hadInput) {
    bool changed = hadInput || evolving_ || touch_.pressing() || !pendingFrames_.empty() ||
                   engine_.session() == nullptr || flow_.state() != composedState_;
    if (session::Session* session = engine_.session()) {
        if (engine_.scansAttached() != shownScan_) {
            painter_.reset();
            shownScan_ = engine_.scansAttached();
        }
        handStructures(*session, flow_.structureList(), flow_.structuresVersion());
        // The views get what the solver and the panel leave of the frame.
        const double left =
            std::max(frameBudget_ - solverSeconds_ - panelSeconds_, frameBudget_ * 0.25);
        changed = painter_.draw(*session, flow_.status(), engine_.levelSetVersion(),
                                engine_.speedVersion(), layout(), left,
                                pacing_.refineSeconds(now_, left, !pendingFrames_.empty())) ||
                  changed;
        const auto [pixels, seconds] = painter_.takeDrawn();
        stats_.drawn(pixels, seconds);
    }
    composed_ = pacing_.screenDue(now_, changed);
    if (!composed_) {
        return;
    }
    composedState_ = flow_.state();
    screen_.begin({0.08F, 0.08F, 0.09F});
    screenState_ = {};
    screenState_.layout = layout();
    if (session::Session* session = engine_.session()) {
        screenState_ = painter_.compose(*session, screenState_.layout, screen_);
    }
    screenState_.structures = &flow_.structureList();
    screenState_.structuresVersion = flow_.structuresVersion();
    panelStart_ = Clock::now();
    glBindFramebuffer(GL_FRAMEBUFFER, screen_.framebuffer());
    // The panel lists the controllers and the DICOM node beside what the workflow publishes.
    shown_ = flow_.status();
    shown_.devices = hub_.links();
    node_.show(shown_);
    for (auto& a : touch_.drawFrame(screen_.size(), now_, screenState_, shown_)) {
        actions_.push_back(std::move(a));
    }
}

void Kiosk::present(Clock::time_point frameStart) {
    if (composed_) {
        screen_.present(display_->framebuffer(), physical_);
        gpu::finish(); // the panel's and the present's cost, for the next frame's split
        panelSeconds_ = 0.8 * panelSeconds_ + 0.2 * secondsSince(panelStart_);
        display_->present();
    }
    lastFrameSeconds_ = secondsSince(frameStart);
    if (engine_.session() != nullptr) { // frames showing a scan: not the wait for a load
        stats_.frame(lastFrameSeconds_, evolving_);
    }
    // Input to screen: from the poll that brought an event to the present of the frame that
    // drew all it led to. A panel button acts, and is drawn, a frame later: its actions
    // are still queued here. A script's operator-level actions are no device's input.
    if (inputSince_ >= 0.0 && actions_.empty()) {
        stats_.latency(secondsSince(start_) - inputSince_);
        inputSince_ = -1.0;
    }
}

void Kiosk::saveFrames() {
    if (pendingFrames_.empty() ||
        !(painter_.settled() || evolving_ || engine_.session() == nullptr)) {
        return;
    }
    const RgbaImage picture = screen_.capture();
    for (const auto& path : pendingFrames_) {
        exports::writeImage(path, picture);
    }
    pendingFrames_.clear();
    stats_.frameWait(secondsSince(start_) - framesAskedAt_);
}

} // namespace steerseg::kiosk
