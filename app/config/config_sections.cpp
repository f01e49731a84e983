#include "config/config_sections.hpp"

#include "model/export_format.hpp"
#include "model/speed_kind.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>

namespace steerseg::config::detail {

namespace {

std::string notEmpty(std::string_view text) {
    return text.empty() ? "must not be empty" : "";
}

// Reads a run of decimal digits at the front of `text` as a positive int; nullopt if none.
std::optional<int> takeNumber(std::string_view& text) {
    int value = 0;
    const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
    if (error != std::errc() || end == text.data() || value <= 0) {
        return std::nullopt;
    }
    text.remove_prefix(static_cast<std::size_t>(end - text.data()));
    return value;
}

// "" (udev's matrix) or six finite numbers separated by blanks, as libinput takes them; the
// KMS backend parses the same text again (config may not include platform/).
std::string calibrationProblem(std::string_view text) {
    if (text.empty()) {
        return "";
    }
    const std::string expected = "expected six numbers separated by blanks, e.g. "
                                 "\"0 1 0 -1 0 1\" for a panel turned 90 degrees, or \"\"";
    int count = 0;
    while (true) {
        while (!text.empty() && (text.front() == ' ' || text.front() == '\t')) {
            text.remove_prefix(1);
        }
        if (text.empty()) {
            break;
        }
        double value = 0.0;
        const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
        if (error != std::errc() || !std::isfinite(value) ||
            (end != text.data() + text.size() && *end != ' ' && *end != '\t')) {
            return expected;
        }
        text.remove_prefix(static_cast<std::size_t>(end - text.data()));
        ++count;
    }
    return count == 6 ? "" : expected;
}

// "" (the preferred mode), "WIDTHxHEIGHT" or "WIDTHxHEIGHT@HZ", as the KMS backend reads it.
std::string modeProblem(std::string_view mode) {
    if (mode.empty()) {
        return "";
    }
    const std::string expected = "expected \"WIDTHxHEIGHT\" or \"WIDTHxHEIGHT@HZ\", e.g. "
                                 "\"1920x1080@60\", or \"\" for the preferred mode";
    std::string_view rest = mode;
    const auto width = takeNumber(rest);
    if (!width || rest.empty() || rest.front() != 'x') {
        return expected;
    }
    rest.remove_prefix(1);
    const auto height = takeNumber(rest);
    if (!height || *width > 16384 || *height > 16384) {
        return expected;
    }
    if (!rest.empty()) {
        if (rest.front() != '@') {
            return expected;
        }
        rest.remove_prefix(1);
        const auto hz = takeNumber(rest);
        if (!hz || !rest.empty() || *hz > 1000) {
            return expected;
        }
    }
    return "";
}

} // namespace

void readDisplay(TableReader& t, DisplayConfig& d) {
    if (auto v = t.text("platform", [](std::string_view word) {
            return parsePlatform(word) ? ""
                                       : "must be \"auto\", \"kms\", \"window\" or \"offscreen\"";
        })) {
        d.platform = *parsePlatform(*v);
    }
    if (auto v = t.integer("width", {64, 16384})) {
        d.width = static_cast<int>(*v);
    }
    if (auto v = t.integer("height", {64, 16384})) {
        d.height = static_cast<int>(*v);
    }
    if (auto v = t.boolean("fullscreen")) {
        d.fullscreen = *v;
    }
    if (auto v = t.text("drm_device", [](std::string_view path) {
            return path.empty() || path.front() == '/' ? ""
                                                       : "must be a device path such as "
                                                         "\"/dev/dri/card0\", or \"\"";
        })) {
        d.drmDevice = *v;
    }
    if (auto v = t.text("connector")) {
        d.connector = *v;
    }
    if (auto v = t.text("mode", modeProblem)) {
        d.mode = *v;
    }
    if (auto v = t.integer("rotation", {0, 270})) {
        if (*v % 90 == 0) {
            d.rotation = static_cast<int>(*v);
        } else {
            t.problem("rotation", "is " + std::to_string(*v) + "; must be 0, 90, 180 or 270");
        }
    }
    if (auto v = t.text("touch_calibration", calibrationProblem)) {
        d.touchCalibration = *v;
    }
    if (auto v = t.number("dpi", {0.0, 1200.0})) {
        if (*v == 0.0 || *v >= 50.0) {
            d.dpi = *v;
        } else {
            t.problem("dpi", "must be 0 (from the display) or at least 50");
        }
    }
}

void readFrame(TableReader& t, FrameConfig& f) {
    if (auto v = t.number("budget_ms", {4.0, 1000.0})) {
        f.budgetMs = *v;
    }
    if (auto v = t.number("solver_share", {0.05, 0.95})) {
        f.solverShare = *v;
    }
    if (auto v = t.integer("min_iterations", {1, 10000})) {
        f.minIterations = static_cast<int>(*v);
    }
    if (auto v = t.integer("max_iterations", {1, 10000})) {
        f.maxIterations = static_cast<int>(*v);
    }
    if (auto v = t.number("interactive_scale", {0.1, 1.0})) {
        f.interactiveScale = *v;
    }
}

void readUi(TableReader& t, UiConfig& ui) {
    if (auto v = t.number("touch_target_mm", {9.0, 40.0})) {
        ui.touchTargetMm = *v;
    }
    if (auto v = t.number("font_scale", {0.5, 4.0})) {
        ui.fontScale = *v;
    }
    if (auto v = t.integer("long_press_ms", {100, 5000})) {
        ui.longPressMs = static_cast<int>(*v);
    }
}

void readProbe(TableReader& t, ProbeConfig& p) {
    if (auto v = t.number("radius_mm", {0.5, 100.0})) {
        p.radiusMm = *v;
    }
    if (auto v = t.number("eps_factor", {0.1, 20.0})) {
        p.epsFactor = *v;
    }
    if (auto v = t.number("eps_floor", {0.0, 1e6})) {
        p.epsFloor = *v;
    }
}

void readSpeed(TableReader& t, SpeedConfig& s) {
    if (auto v = t.text("kind", [](std::string_view word) {
            return model::parseSpeedKind(word) ? ""
                                               : "must be \"threshold\", \"edge\" or \"classify\"";
        })) {
        s.kind = *model::parseSpeedKind(*v);
    }
    if (auto v = t.boolean("classify_within_window")) {
        s.classifyWithinWindow = *v;
    }
    if (auto v = t.number("classify_place_reach", {0.0, 100.0})) {
        s.classifyPlaceReach = *v;
    }
    if (auto v = t.integer("smooth_iterations", {0, 1000})) {
        s.smoothIterations = static_cast<int>(*v);
    }
    if (auto v = t.number("conductance_factor", {0.0, 10.0, true})) {
        s.conductanceFactor = *v;
    }
    if (auto v = t.number("kappa_factor", {0.0, 10.0, true})) {
        s.kappaFactor = *v;
    }
}

void readBrush(TableReader& t, BrushConfig& b) {
    if (auto v = t.number("radius", {0.5, 256.0})) {
        b.radius = *v;
    }
    if (auto v = t.number("correction_reach", {0.0, 100.0})) {
        b.correctionReach = *v;
    }
    if (auto v = t.number("erase_run_growth", {0.0, 100.0})) {
        b.eraseRunGrowth = *v;
    }
    if (auto v = t.number("erase_withdraw_mm", {0.0, 1000.0})) {
        b.eraseWithdrawMm = *v;
    }
}

void readExport(TableReader& t, ExportConfig& e) {
    if (auto v = t.text("folder", notEmpty)) {
        e.folder = *v;
    }
    const toml::array* formats = t.array("formats");
    if (formats == nullptr) {
        return;
    }
    std::vector<std::string> read;
    bool good = true;
    for (std::size_t i = 0; i < formats->size(); ++i) {
        const std::string key = t.path("formats") + '[' + std::to_string(i) + ']';
        auto format = readText(
            *formats->get(i), key,
            [&read](std::string_view f) -> std::string {
                const auto& known = model::exportFormats();
                if (std::none_of(known.begin(), known.end(), [f](model::ExportFormat k) {
                        return model::exportFormatName(k) == f;
                    })) {
                    return "unknown format \"" + std::string(f) +
                           "\"; known: " + model::exportFormatNames();
                }
                if (std::find(read.begin(), read.end(), f) != read.end()) {
                    return "\"" + std::string(f) + "\" is listed twice";
                }
                return "";
            },
            t.sink());
        if (format) {
            read.push_back(*format);
        } else {
            good = false;
        }
    }
    if (good && read.empty()) {
        t.problem("formats", "must name at least one format (" + model::exportFormatNames() + ")");
        good = false;
    }
    if (good) {
        e.formats = std::move(read);
    }
}

void readAudit(TableReader& t, AuditConfig& a) {
    if (auto v = t.text("path", notEmpty)) {
        a.path = *v;
    }
}

void readAutosave(TableReader& t, AutosaveConfig& a) {
    if (auto v = t.text("folder", notEmpty)) {
        a.folder = *v;
    }
    if (auto v = t.number("interval_seconds", {1.0, 3600.0})) {
        a.intervalSeconds = *v;
    }
    if (auto v = t.integer("keep", {2, 1000})) {
        a.keep = static_cast<int>(*v);
    }
}

void checkRelations(const KioskConfig& config, const toml::table& root, ProblemSink& sink) {
    if (config.frame.minIterations > config.frame.maxIterations) {
        // Name the side this file set (both, or one over an earlier layer's other).
        const toml::node* frame = root.get("frame");
        const toml::table* table = frame != nullptr ? frame->as_table() : nullptr;
        const toml::node* at = nullptr;
        std::string key = "frame.max_iterations";
        if (table != nullptr) {
            at = table->get("max_iterations");
            if (at == nullptr) {
                at = table->get("min_iterations");
                key = "frame.min_iterations";
            }
        }
        sink.add(at != nullptr ? at->source() : root.source(), key,
                 "min_iterations (" + std::to_string(config.frame.minIterations) +
                     ") is above max_iterations (" + std::to_string(config.frame.maxIterations) +
                     ")");
    }
    checkDicomTls(config.dicom, root, sink);
}

} // namespace steerseg::config::detail
