#pragma once

// The kiosk's three views, drawn each frame within their share of the frame's time and placed
// on the logical screen. Each view redraws only when what it shows changed (camera, slice,
// window, parameters, the level set), as a preview sized to fit the frame, then refines to full
// resolution in tiles while still (ViewRefiner). Each view keeps two of the renderer's
// pictures: the preview stays on screen until the full picture is complete.
#include "kiosk/screen_compositor.hpp"
#include "kiosk/view_refiner.hpp"
#include "render/render_params.hpp"
#include "render/slice_frame.hpp"
#include "session/session.hpp"
#include "ui/screen_state.hpp"
#include "workflow/status.hpp"

#include <array>
#include <cstdint>
#include <optional>
#include <string>

namespace steerseg::kiosk {

class ViewPainter {
  public:
    explicit ViewPainter(double interactiveScale);

    // Draws what is due: previews within `seconds`, refinement tiles within `refineSeconds`
    // (OperatorPacing: more once nobody touches anything), shared by the views that have
    // work. A change of levelSetVersion redraws every view, of speedVersion the speed view.
    // Returns whether a picture on screen changed (a preview, a completed full picture).
    bool draw(session::Session& session, const workflow::Status& status,
              std::uint64_t levelSetVersion, std::uint64_t speedVersion, const ui::Layout& layout,
              double seconds, double refineSeconds);
    // Every view's latest picture into its rect. Returns where the slice views are and which
    // slice frames their pictures show.
    ui::ScreenState compose(session::Session& session, const ui::Layout& layout,
                            ScreenCompositor& screen) const;
    // Every view shows its full-resolution picture of the current state.
    [[nodiscard]] bool settled() const;
    // A new scan: nothing drawn is valid any more.
    void reset();
    // Pixels drawn since the last call, and the seconds spent (the benchmark's rates).
    std::pair<double, double> takeDrawn();

  private:
    struct View {
        ViewRefiner refiner;
        std::string signature;
        int previewTarget = 0;
        int fullTarget = 0;
        int shownTarget = -1; // -1: nothing drawn since the last reset
        std::optional<render::SliceFrame> shownFrame;
        std::optional<render::Camera> shownCamera; // the 3D view's, for the UI's overlays
    };
    // Draws what is due for one view; true when its picture on screen changed.
    bool paintView(View& view, session::Session& session, render::ViewParams params, double seconds,
                   double refineSeconds);

    std::array<View, 3> views_;
    double drawnPixels_ = 0.0;
    double drawnSeconds_ = 0.0;
};

} // namespace steerseg::kiosk
