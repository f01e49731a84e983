#include "config/config_loader.hpp"

#include "config/config_sections.hpp"
#include "config/toml_table_reader.hpp"

#include <algorithm>
#include <cerrno>
#include <climits>
#include <cstring>
#include <fstream>
#include <stdexcept>

namespace steerseg::config {

namespace {

namespace fs = std::filesystem;

ConfigProblem fileProblem(const fs::path& path, std::string message) {
    return {path.string(), 0, 0, "", std::move(message)};
}

// The file's text, or nullopt with the reason in `problems` (nothing for a missing optional
// file). Reads at most kMaxConfigBytes + 1 bytes, so neither a huge file nor a device that
// never ends (a FIFO is not a regular file and is refused before) holds the kiosk up.
std::optional<std::string> readLayer(const ConfigSource& source,
                                     std::vector<ConfigProblem>& problems) {
    std::error_code error;
    const fs::file_status status = fs::status(source.path, error);
    if (status.type() == fs::file_type::not_found) {
        if (source.required) {
            problems.push_back(fileProblem(source.path, "no such file"));
        }
        return std::nullopt;
    }
    if (error) {
        problems.push_back(fileProblem(source.path, "cannot be read: " + error.message()));
        return std::nullopt;
    }
    if (status.type() != fs::file_type::regular) {
        problems.push_back(fileProblem(source.path, "is not a regular file"));
        return std::nullopt;
    }
    const auto tooLarge = [&] {
        problems.push_back(fileProblem(
            source.path, "is larger than 1 MiB, too large for a configuration; not read"));
    };
    if (const std::uintmax_t size = fs::file_size(source.path, error);
        !error && size > kMaxConfigBytes) {
        tooLarge();
        return std::nullopt;
    }
    std::ifstream in(source.path, std::ios::binary);
    if (!in) {
        problems.push_back(
            fileProblem(source.path, std::string("cannot be read: ") + std::strerror(errno)));
        return std::nullopt;
    }
    std::string text(kMaxConfigBytes + 1, '\0');
    in.read(text.data(), static_cast<std::streamsize>(text.size()));
    if (in.bad()) {
        problems.push_back(fileProblem(source.path, "cannot be read: read error"));
        return std::nullopt;
    }
    text.resize(static_cast<std::size_t>(in.gcount()));
    if (text.size() > kMaxConfigBytes) { // it grew after the size check
        tooLarge();
        return std::nullopt;
    }
    return text;
}

// The built-in bindings go through the same check as a file's: an action the workflow does
// not know is a bug to report, and the binding is dropped rather than left to fail on a press.
void checkDefaultBindings(KioskConfig& config, const BindingCheck& check,
                          std::vector<ConfigProblem>& problems) {
    const auto checkTable = [&](BindingTable& table, std::string_view name) {
        for (auto it = table.begin(); it != table.end();) {
            if (check(it->second.action) &&
                (it->second.release.empty() || check(it->second.release))) {
                ++it;
                continue;
            }
            problems.push_back(
                {"built-in defaults", 0, 0,
                 detail::keyPath("bindings." + std::string(name), it->first),
                 "\"" + (check(it->second.action) ? it->second.release : it->second.action) +
                     "\" is not an action a control can do; binding dropped"});
            it = table.erase(it);
        }
    };
    checkTable(config.bindings.keys, "keys");
    checkTable(config.bindings.knobs, "knobs");
    checkTable(config.bindings.buttons, "buttons");
}

} // namespace

std::vector<ConfigSource> kioskConfigSources(const std::optional<fs::path>& commandLine) {
    std::vector<ConfigSource> sources{{fs::path(kSystemConfigPath), false}};
    if (commandLine) {
        sources.push_back({*commandLine, true});
    }
    return sources;
}

std::vector<ConfigProblem> applyConfigText(KioskConfig& config, std::string_view text,
                                           const std::string& file, const BindingCheck& check) {
    if (!check) {
        throw std::invalid_argument("config: no binding check given");
    }
    toml::table root;
    try {
        root = toml::parse(text, std::string_view(file));
    } catch (const toml::parse_error& error) {
        const toml::source_position at = error.source().begin;
        return {{file, static_cast<int>(at.line), static_cast<int>(at.column), "",
                 std::string(error.description())}};
    }
    detail::ProblemSink sink(file);
    KioskConfig next = config;
    detail::TableReader top(root, "", sink);
    const auto section = [&](std::string_view name, auto read, auto& into) {
        if (const toml::table* table = top.table(name)) {
            detail::TableReader reader(*table, std::string(name), sink);
            read(reader, into);
            reader.reportUnknownKeys();
        }
    };
    section("display", detail::readDisplay, next.display);
    section("frame", detail::readFrame, next.frame);
    section("ui", detail::readUi, next.ui);
    section("probe", detail::readProbe, next.probe);
    section("brush", detail::readBrush, next.brush);
    section("speed", detail::readSpeed, next.speed);
    section("export", detail::readExport, next.exports);
    section("audit", detail::readAudit, next.audit);
    section("autosave", detail::readAutosave, next.autosave);
    section("dicom", detail::readDicom, next.dicom);
    section("segmentation", detail::readSegmentation, next.segmentation);
    if (const toml::table* bindings = top.table("bindings")) {
        detail::TableReader reader(*bindings, "bindings", sink);
        detail::readBindings(reader, next.bindings, check);
    }
    if (const toml::table* input = top.table("input")) {
        detail::TableReader reader(*input, "input", sink);
        if (const toml::array* devices = reader.array("devices")) {
            detail::readInputDevices(*devices, next.input.devices, sink);
        }
        reader.reportUnknownKeys();
    }
    if (const toml::array* presets = top.array("preset")) {
        detail::readPresets(*presets, next.presets, sink);
    }
    if (const toml::array* structures = top.array("structures")) {
        detail::readStructures(*structures, next.structures, sink);
    }
    top.reportUnknownKeys();
    if (sink.empty()) {
        detail::checkRelations(next, root, sink);
    }
    if (sink.empty()) {
        config = std::move(next);
    }
    // In the file's order (tables are read in key order); a whole-file note (line 0) last.
    std::vector<ConfigProblem> problems = sink.take();
    std::stable_sort(problems.begin(), problems.end(),
                     [](const ConfigProblem& a, const ConfigProblem& b) {
                         const auto order = [](const ConfigProblem& p) {
                             return std::pair(p.line > 0 ? p.line : INT_MAX, p.column);
                         };
                         return order(a) < order(b);
                     });
    return problems;
}

LoadedConfig loadConfig(const std::vector<ConfigSource>& layers, const BindingCheck& check) {
    if (!check) {
        throw std::invalid_argument("config: no binding check given");
    }
    LoadedConfig loaded{defaultConfig(), {}, {}};
    checkDefaultBindings(loaded.config, check, loaded.problems);
    for (const ConfigSource& layer : layers) {
        const std::optional<std::string> text = readLayer(layer, loaded.problems);
        if (!text) {
            continue;
        }
        std::vector<ConfigProblem> problems =
            applyConfigText(loaded.config, *text, layer.path.string(), check);
        if (problems.empty()) {
            loaded.applied.push_back(layer.path);
        }
        loaded.problems.insert(loaded.problems.end(), std::make_move_iterator(problems.begin()),
                               std::make_move_iterator(problems.end()));
    }
    return loaded;
}

} // namespace steerseg::config
