#pragma once

// The kiosk's configuration as a command other than the kiosk reads it (the shipped defaults,
// the system file, --config), every problem printed as "steerseg COMMAND: config: ...".
#include "config/config_loader.hpp"

#include <optional>
#include <ostream>
#include <string>

namespace steerseg::cli {

config::LoadedConfig readKioskConfig(const std::optional<std::string>& file,
                                     const std::string& command, std::ostream& err);

} // namespace steerseg::cli
