#pragma once

// The workflow's view state -> the renderer's parameters for the kiosk's three views: the 3D
// view turned about the scan's centre, the first slice view with the yellow contour, the second
// with the speed function's data term under it (the paper's Figure 7).
#include "render/render_params.hpp"
#include "session/session.hpp"
#include "workflow/status.hpp"

namespace steerseg::engine {

render::ViewKind viewKindOf(model::SliceAxis axis);

render::ViewParams volumeViewParams(const session::Session& session, const workflow::Status& status,
                                    const glm::ivec2& size);
// `speed`: the second slice view, which shows the data term eps - |I - T| under the contour.
// The caller picks the picture (ViewParams::target) and the region.
render::ViewParams sliceViewParams(const session::Session& session, const workflow::Status& status,
                                   model::SliceAxis axis, bool speed, const glm::ivec2& size);

} // namespace steerseg::engine
