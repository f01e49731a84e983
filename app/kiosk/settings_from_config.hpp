#pragma once

// The configuration's parts that the workflow and the display take, in their own types.
#include "config/kiosk_config.hpp"
#include "platform/display.hpp"
#include "workflow/settings.hpp"

namespace steerseg::kiosk {

workflow::Settings workflowSettings(const config::KioskConfig& config);
platform::DisplayOptions displayOptions(const config::DisplayConfig& display);

} // namespace steerseg::kiosk
