#pragma once

// What a gesture means now: a recognised gesture, the region it began in, the workflow's
// status and the slice views as drawn -> workflow actions. The workflow decides whether an
// action applies; this only names the operator's intent (a tap on a slice while seeding is a
// seed at the voxel under the finger). Taps on the panel belong to ImGui, not here.
// A one-finger drag on a slice paints where a tap would place a sphere (add, erase or outside
// mode): the path is collected while the finger moves and sent as ONE model::PaintStroke when
// it lifts, so the stroke is one undo step, one audit record and one retraining of classify
// (retraining per piece would stall every frame of the drag); a second finger landing cancels
// it. Elsewhere (inspect's probing, review) a one-finger drag pages; two fingers page always.
// In box mode (Status::boxMode) a one-finger drag draws the box instead: its rectangle sets the
// box's extent on the view's two axes, or, begun on an edge of the box's rectangle, moves that
// face alone; ONE model::SetBox goes when the finger lifts (one undo step), and a tap does
// nothing.
#include "model/action.hpp"
#include "ui/gestures.hpp"
#include "ui/layout.hpp"
#include "ui/screen_state.hpp"
#include "ui/slice_mapping.hpp"
#include "workflow/status.hpp"

#include <optional>
#include <vector>

namespace steerseg::ui {

struct InteractionConfig {
    double probeRadiusMm = 5.0; // config: probe radius
    double pxPerSlice = 12.0;   // vertical drag on a slice: one slice per this many pixels
    double degreesPerPx = 0.4;  // drag on the 3D view
    double zoomPerDetent = 1.1; // wheel on the 3D view
    double boxEdgePx = 8.0;     // box mode: a drag begun this near an edge of the box moves it
};
// pxPerSlice of 1.5 mm at `dpi`, so a finger pages at the same physical rate on every screen.
InteractionConfig interactionConfig(double dpi, double probeRadiusMm);

class Interaction {
  public:
    explicit Interaction(InteractionConfig config = {});

    std::vector<model::Action> onGesture(const Gesture& gesture, const ScreenState& screen,
                                         const workflow::Status& status);

    // The stroke being painted, in screen pixels as the finger went (empty when none), for the
    // screen to draw under the finger until it lifts; and its mode.
    [[nodiscard]] const std::vector<glm::dvec2>& strokePath() const;
    [[nodiscard]] std::optional<model::StrokeMode> strokeMode() const;
    // Box mode: the box the finger is drawing or moving, as it would be if it lifted now
    // (nullopt when none), for the screen to show in every view until it lifts.
    [[nodiscard]] std::optional<model::Box> boxDraft() const;

  private:
    struct Stroke {
        int id = -1; // the drag's
        model::StrokeMode mode = model::StrokeMode::Add;
        std::vector<glm::dvec3> points; // voxels, within the scan
        std::vector<glm::dvec2> screen;
    };
    struct BoxDrag {
        int id = -1;                        // the drag's
        std::optional<model::BoxFace> face; // moving this face; none: drawing the extent
        glm::dvec3 from{0.0};               // the voxel where the finger went down
        std::optional<model::Box> before;   // the box when it went down
        model::Box box;                     // what it makes so far
    };
    std::vector<model::Action> paint(const Gesture& g, const SliceView& view,
                                     const workflow::Status& status);
    void beginBox(const Gesture& g, const SliceView& view, const workflow::Status& status);
    std::vector<model::Action> dragBox(const Gesture& g, const SliceView& view,
                                       const workflow::Status& status);
    std::vector<model::Action> onSlice(const Gesture& g, const SliceView& view,
                                       model::SliceAxis axis, const workflow::Status& status);
    std::vector<model::Action> onView3d(const Gesture& g);
    static std::vector<model::Action> page(model::SliceAxis axis, double& accumulated,
                                           double amount);

    InteractionConfig config_;
    int dragId_ = -1; // the drag whose paging remainder `dragSlices_` holds
    double dragSlices_ = 0.0;
    double wheelSlices_ = 0.0; // fractional detents (touchpads) carried between events
    int pinchId_ = -1;         // the two-finger drag whose paging remainder `pinchSlices_` holds
    double pinchSlices_ = 0.0;
    std::optional<Stroke> stroke_;
    std::optional<BoxDrag> boxDrag_;
};

} // namespace steerseg::ui
