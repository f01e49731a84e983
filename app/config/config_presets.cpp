#include "config/config_sections.hpp"

#include <algorithm>

namespace steerseg::config::detail {

namespace {

constexpr std::size_t kMaxPresets = 32; // the panel's list, not a database
constexpr std::size_t kMaxNameBytes = 64;
constexpr double kHuge = 1e9; // any real unit a scan stores, and no inf or nan

std::string nameProblem(std::string_view name) {
    if (name.empty()) {
        return "must not be empty";
    }
    return name.size() > kMaxNameBytes ? "is longer than 64 bytes" : "";
}

// Reads the fields `entry` gives into `preset`; returns the required fields it lacks.
std::vector<std::string> readFields(TableReader& t, Preset& preset) {
    std::vector<std::string> missing;
    const auto number = [&](std::string_view key, double& out, const NumberRange& range) {
        if (!t.has(key)) {
            missing.emplace_back(key);
        }
        if (auto v = t.number(key, range)) {
            out = *v;
        }
    };
    number("T", preset.T, {-kHuge, kHuge});
    number("eps", preset.eps, {0.0, kHuge, true});
    number("alpha", preset.alpha, {0.0, 1.0});
    number("window_level", preset.windowLevel, {-kHuge, kHuge});
    number("window_width", preset.windowWidth, {0.0, kHuge, true});
    if (!t.has("transfer")) {
        missing.emplace_back("transfer");
    }
    if (auto v = t.text("transfer", [](std::string_view s) {
            return s.empty() ? "must name a transfer function (\"soft\", \"bone\", \"mr\")" : "";
        })) {
        preset.transfer = *v;
    }
    return missing;
}

} // namespace

void readPresets(const toml::array& entries, std::vector<Preset>& presets, ProblemSink& sink) {
    std::vector<std::string> seen; // names given in this file
    for (std::size_t i = 0; i < entries.size(); ++i) {
        const toml::node& node = *entries.get(i);
        const std::string prefix = "preset[" + std::to_string(i + 1) + "]";
        const toml::table* table = node.as_table();
        if (table == nullptr) {
            sink.add(node.source(), prefix, "expected a table ([[preset]]), got something else");
            continue;
        }
        TableReader t(*table, prefix, sink);
        const auto name = t.text("name", nameProblem);
        if (!t.has("name")) {
            sink.add(table->source(), prefix, "has no name");
        }
        if (name && std::find(seen.begin(), seen.end(), *name) != seen.end()) {
            t.problem("name", "\"" + *name + "\" is given twice in this file");
        }
        const auto existing = std::find_if(presets.begin(), presets.end(), [&](const Preset& p) {
            return name && p.name == *name;
        });
        if (existing != presets.end()) {
            readFields(t, *existing); // an override gives only what it changes
        } else {
            Preset preset;
            const std::vector<std::string> missing = readFields(t, preset);
            if (name && !missing.empty()) {
                std::string list;
                for (const std::string& key : missing) {
                    list += (list.empty() ? "" : ", ") + key;
                }
                sink.add(table->source(), prefix,
                         "new preset \"" + *name + "\" lacks " + list +
                             " (only an existing preset's name may give some fields)");
            }
            if (name && presets.size() >= kMaxPresets) {
                sink.add(table->source(), prefix, "more than 32 presets");
            }
            preset.name = name.value_or("");
            presets.push_back(std::move(preset));
        }
        if (name) {
            seen.push_back(*name);
        }
        t.reportUnknownKeys();
    }
}

} // namespace steerseg::config::detail
