// The configuration reader on arbitrary text: no crash, no hang, and every problem one line
// that names its file; a text with problems leaves the configuration as it was.
#include "config/config_loader.hpp"

#include <cstdint>
#include <cstdlib>
#include <string_view>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    using namespace steerseg::config;
    const std::string_view text(reinterpret_cast<const char*>(data), size);
    const BindingCheck check = [](std::string_view action) {
        return action == "run" || action == "undo" || action == "nudge_selected";
    };
    KioskConfig config = defaultConfig();
    const std::vector<ConfigProblem> problems = applyConfigText(config, text, "fuzz.toml", check);
    for (const ConfigProblem& problem : problems) {
        const std::string line = describe(problem);
        if (line.find('\n') != std::string::npos || problem.file != "fuzz.toml" ||
            problem.message.empty()) {
            std::abort();
        }
    }
    if (!problems.empty() && !(config == defaultConfig())) {
        std::abort();
    }
    return 0;
}
