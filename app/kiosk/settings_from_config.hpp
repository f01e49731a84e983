#pragma once

// The configuration's parts that the workflow and the display take, in their own types.
#include "config/kiosk_config.hpp"
#include "platform/display.hpp"
#include "session/numerics_check.hpp"
#include "workflow/settings.hpp"

namespace steerseg::kiosk {

// `numerics`: the start-up check of this GPU (session/numerics_check), or null. Each speed it
// failed is off (workflow::Settings::speedsOff); when the configured speed is one of them, the
// first that passed (the threshold speed first) runs after a load instead.
workflow::Settings workflowSettings(const config::KioskConfig& config,
                                    const session::NumericsReport* numerics = nullptr);
platform::DisplayOptions displayOptions(const config::DisplayConfig& display);

} // namespace steerseg::kiosk
