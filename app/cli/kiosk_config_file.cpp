#include "cli/kiosk_config_file.hpp"

#include "model/action.hpp"

#include <filesystem>

namespace steerseg::cli {

config::LoadedConfig readKioskConfig(const std::optional<std::string>& file,
                                     const std::string& command, std::ostream& err) {
    const config::BindingCheck check = model::isBindable;
    std::optional<std::filesystem::path> path;
    if (file) {
        path = *file;
    }
    config::LoadedConfig loaded = config::loadConfig(config::kioskConfigSources(path), check);
    for (const config::ConfigProblem& p : loaded.problems) {
        err << "steerseg " << command << ": config: " << config::describe(p) << '\n';
    }
    return loaded;
}

} // namespace steerseg::cli
