#pragma once

// Reads the kiosk's configuration in layers: the built-in defaults, then the system file, then
// the operator's --config file, each overriding the ones below key by key. A file with any
// problem (syntax, unknown key, wrong type, value out of range, unknown action) is not applied
// at all, so the kiosk starts on the layers below it; every problem is reported.
#include "config/config_problem.hpp"
#include "config/kiosk_config.hpp"

#include <cstdint>
#include <filesystem>
#include <functional>
#include <optional>
#include <string_view>
#include <vector>

namespace steerseg::config {

inline constexpr std::string_view kSystemConfigPath = "/etc/steerseg/steerseg.toml";
inline constexpr std::uintmax_t kMaxConfigBytes = std::uintmax_t{1} << 20;

// Whether an action name may be bound. The kiosk passes the workflow's own check
// (model::bindingAction(name, 1).has_value()), so config needs no workflow code at link time.
using BindingCheck = std::function<bool(std::string_view action)>;

struct ConfigSource {
    std::filesystem::path path;
    bool required = true; // a missing required file is a problem; a missing optional one is not
};

// The system file (optional) and, when given, the command line's --config file (required).
std::vector<ConfigSource>
kioskConfigSources(const std::optional<std::filesystem::path>& commandLine);

struct LoadedConfig {
    KioskConfig config;
    std::vector<ConfigProblem> problems;        // every layer's, in order
    std::vector<std::filesystem::path> applied; // the files that took effect
};

// defaultConfig() with `layers` applied in order. The defaults' own bindings are checked too
// (file "built-in defaults"): a binding the workflow does not know is reported and dropped.
// Throws std::invalid_argument for an empty check (a programming error, not a file's).
LoadedConfig loadConfig(const std::vector<ConfigSource>& layers, const BindingCheck& check);

// One layer given as text, `file` naming it in problems: applied to `config` when it has no
// problem, else `config` is left as it was. Returns the problems.
std::vector<ConfigProblem> applyConfigText(KioskConfig& config, std::string_view text,
                                           const std::string& file, const BindingCheck& check);

} // namespace steerseg::config
