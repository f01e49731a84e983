#pragma once

// What a gesture means now: a recognised gesture, the region it began in, the workflow's
// status and the slice views as drawn -> workflow actions. The workflow decides whether an
// action applies; this only names the operator's intent (a tap on a slice while seeding is a
// seed at the voxel under the finger). Taps on the panel belong to ImGui, not here.
#include "model/action.hpp"
#include "ui/gestures.hpp"
#include "ui/layout.hpp"
#include "ui/screen_state.hpp"
#include "ui/slice_mapping.hpp"
#include "workflow/status.hpp"

#include <vector>

namespace steerseg::ui {

struct InteractionConfig {
    double probeRadiusMm = 5.0; // config: probe radius
    double pxPerSlice = 12.0;   // vertical drag on a slice: one slice per this many pixels
    double degreesPerPx = 0.4;  // drag on the 3D view
    double zoomPerDetent = 1.1; // wheel on the 3D view
};
// pxPerSlice of 1.5 mm at `dpi`, so a finger pages at the same physical rate on every screen.
InteractionConfig interactionConfig(double dpi, double probeRadiusMm);

class Interaction {
  public:
    explicit Interaction(InteractionConfig config = {});

    std::vector<model::Action> onGesture(const Gesture& gesture, const ScreenState& screen,
                                         const workflow::Status& status);

  private:
    std::vector<model::Action> onSlice(const Gesture& g, const SliceView& view,
                                       model::SliceAxis axis, const workflow::Status& status);
    std::vector<model::Action> onView3d(const Gesture& g);
    static std::vector<model::Action> page(model::SliceAxis axis, double& accumulated,
                                           double amount);

    InteractionConfig config_;
    int dragId_ = -1; // the drag whose paging remainder `dragSlices_` holds
    double dragSlices_ = 0.0;
    double wheelSlices_ = 0.0; // fractional detents (touchpads) carried between events
};

} // namespace steerseg::ui
