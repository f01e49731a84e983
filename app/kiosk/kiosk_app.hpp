#pragma once

// `steerseg kiosk`: the appliance program. One loop owns the GL context: poll input (the
// display's, a script's), feed the workflow, step the solver within its share of the frame,
// draw the views and the panel, present.
#include "kiosk/kiosk_options.hpp"

#include <iosfwd>

namespace steerseg::kiosk {

// Runs until the operator quits, the display goes away, SIGTERM/SIGINT, or the script ends.
// Returns 0, or 1 when a script step failed (its reason on `err`). Throws
// platform::DisplayError when no display opens.
int runKiosk(const KioskOptions& options, std::ostream& out, std::ostream& err);

} // namespace steerseg::kiosk
