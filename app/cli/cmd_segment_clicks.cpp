// steerseg segment --click and --box: an operator's prompts replayed through the kiosk's workflow
// (engine::ClickSession), so that a case of the steering benchmark is reproducible from the
// command line (docs/steering.md).
#include "cli/args.hpp"
#include "cli/commands.hpp"
#include "cli/kiosk_config_file.hpp"
#include "cli/segment_clicks.hpp"
#include "core/mask_overlap.hpp"
#include "engine/click_session.hpp"
#include "files/file_write.hpp"
#include "kiosk/settings_from_config.hpp"
#include "model/export_format.hpp"
#include "platform/egl/offscreen_context.hpp"
#include "scan/scan_reader.hpp"

#include <cstddef>
#include <cstdio>
#include <iostream>
#include <limits>
#include <nlohmann/json.hpp>
#include <optional>
#include <stdexcept>
#include <variant>

namespace steerseg::cli {

namespace {

// The default cap of iterations after each click (the clicks protocol's).
constexpr int kClickIterations = 3000;

} // namespace

void writeReport(const std::string& path, const std::string& text) {
    const std::string whole = text + "\n";
    files::writeFileAtomically(path, {std::as_bytes(std::span(whole.data(), whole.size()))});
}

namespace {

std::vector<std::string> commaFields(const std::string& text) {
    std::vector<std::string> parts;
    std::size_t from = 0;
    for (std::size_t at = text.find(',');; at = text.find(',', from)) {
        parts.push_back(text.substr(from, at == std::string::npos ? std::string::npos : at - from));
        if (at == std::string::npos) {
            break;
        }
        from = at + 1;
    }
    return parts;
}

} // namespace

model::Box parseBox(const std::string& text) {
    const std::vector<std::string> parts = commaFields(text);
    if (parts.size() != 6) {
        throw UsageError("--box '" + text + "': expected 6 fields, got " +
                         std::to_string(parts.size()) + " (give i0,j0,k0,i1,j1,k1)");
    }
    model::Box box;
    for (int n = 0; n < 6; ++n) {
        const long long v = parseInteger(parts[static_cast<std::size_t>(n)], "--box's voxel index");
        if (v < 0 || v > std::numeric_limits<int>::max()) {
            throw UsageError("--box '" + text + "': voxel indices start at 0");
        }
        (n < 3 ? box.lo : box.hi)[n % 3] = static_cast<int>(v);
    }
    for (int a = 0; a < 3; ++a) {
        if (box.lo[a] > box.hi[a]) {
            throw UsageError("--box '" + text + "': inverted on axis " + "ijk"[a] +
                             " (give i0 <= i1, j0 <= j1, k0 <= k1)");
        }
    }
    return box;
}

model::Correct parseClick(const std::string& text) {
    const auto fail = [&text](const std::string& why) {
        return UsageError("--click '" + text + "': " + why +
                          " (give i,j,k,+ or i,j,k,- [,radius])");
    };
    const std::vector<std::string> parts = commaFields(text);
    if (parts.size() != 4 && parts.size() != 5) {
        throw fail("expected 4 or 5 fields, got " + std::to_string(parts.size()));
    }
    model::Correct c;
    for (int a = 0; a < 3; ++a) {
        c.voxel[a] = parseNumber(parts[static_cast<std::size_t>(a)], "--click's voxel index");
    }
    if (parts[3] != "+" && parts[3] != "-") {
        throw fail("the fourth field must be + or -");
    }
    c.positive = parts[3] == "+";
    if (parts.size() == 5) {
        c.radius = parseNumber(parts[4], "--click's radius");
        if (!(c.radius > 0.0)) {
            throw fail("the radius must be > 0");
        }
    }
    return c;
}

int runSegmentClicks(const Args& args) {
    static const std::vector<std::string> kExcluded{
        "seed",  "erase", "barrier", "probe", "inside", "outside",     "iterations", "time",
        "speed", "T",     "eps",     "alpha", "smooth", "conductance", "kappa"};
    for (const std::string& name : kExcluded) {
        if (args.value(name)) {
            throw UsageError("--" + name +
                             " does not go with --click or --box: the prompts set the seeds, "
                             "and T, eps and the speed come as the kiosk's (--config)");
        }
    }
    for (const char* flag : {"converge", "dense", "stop-on-leak"}) {
        if (args.flag(flag)) {
            throw UsageError(std::string("--") + flag +
                             " does not go with --click or --box: each prompt runs to the "
                             "solver's own stop, leaks included, as in the kiosk");
        }
    }
    std::optional<model::Box> box;
    if (const auto text = args.value("box")) {
        box = parseBox(*text);
    }
    std::vector<model::Correct> clicks;
    for (const std::string& text : args.values("click")) {
        clicks.push_back(parseClick(text));
    }
    if (!box && !clicks.front().positive) {
        throw UsageError("the first --click must be positive (+): it probes and seeds");
    }
    int cap = kClickIterations;
    if (const auto n = args.value("max-iterations")) {
        cap = static_cast<int>(parseInteger(*n, "--max-iterations"));
        if (cap < 1) {
            throw UsageError("--max-iterations must be >= 1");
        }
    }
    const std::string input = args.required("input");
    const std::string output = args.required("output");
    model::ExportFormat format{};
    try {
        format = model::exportFormatFor(output, args.value("format"));
    } catch (const std::invalid_argument& e) {
        throw UsageError(e.what());
    }
    const config::LoadedConfig loaded = readKioskConfig(args.value("config"), "segment", std::cerr);
    const config::KioskConfig& cfg = loaded.config;
    std::optional<Volume> reference;
    int referenceLabel = -1;
    if (const auto file = args.value("reference")) {
        reference = scan::readScan(*file).volume;
        if (const auto label = args.value("reference-label")) {
            referenceLabel = static_cast<int>(parseNumber(*label, "--reference-label"));
        }
    }

    auto context = platform::createOffscreenContext();
    engine::ClickSession session(
        input, kiosk::workflowSettings(cfg),
        {cfg.speed.smoothIterations, cfg.speed.conductanceFactor, cfg.speed.kappaFactor});
    for (const model::Correct& c : clicks) {
        if (const std::string problem = session.workflow().correctionRadiusProblem(c.radius);
            !problem.empty()) {
            throw UsageError("--click: " + problem);
        }
    }
    if (box) {
        try {
            model::validateBox(*box, session.scan().dims());
        } catch (const std::invalid_argument& e) {
            throw UsageError(std::string("--box: ") + e.what());
        }
    }
    if (reference && reference->dims() != session.scan().dims()) {
        throw UsageError("--reference is not on the scan's grid (" + dimsText(reference->dims()) +
                         " voxels, the scan " + dimsText(session.scan().dims()) + ")");
    }
    // The box is step 0 when given (the challenge's protocol: docs/steering.md), the clicks
    // corrections after it; without one the first click is step 0.
    std::vector<model::Action> prompts;
    if (box) {
        prompts.emplace_back(model::SetBox{*box});
    }
    prompts.insert(prompts.end(), clicks.begin(), clicks.end());
    nlohmann::ordered_json steps = nlohmann::ordered_json::array();
    for (std::size_t n = 0; n < prompts.size(); ++n) {
        const engine::ClickOutcome r = session.apply(prompts[n], cap);
        nlohmann::ordered_json j;
        j["click"] = n;
        if (const auto* c = std::get_if<model::Correct>(&prompts[n])) {
            j["kind"] = n == 0 ? "initial" : (c->positive ? "positive" : "negative");
            j["voxel"] = {c->voxel.x, c->voxel.y, c->voxel.z};
        } else {
            j["kind"] = "box";
            j["box"] = {box->lo.x, box->lo.y, box->lo.z, box->hi.x, box->hi.y, box->hi.z};
        }
        j["stop_reason"] = r.stopReason;
        if (!r.leakWatch.empty()) {
            j["leak_watch"] = r.leakWatch;
        }
        j["iterations"] = r.iterations;
        j["seconds"] = r.seconds;
        j["first_change_seconds"] = r.firstChangeSeconds;
        j["T"] = r.T;
        j["eps"] = r.eps;
        j["barriers"] = r.barriers;
        j["taken_back"] = r.takenBack;
        j["withdraw_only"] = r.withdrawOnly;
        if (reference) {
            j["dice"] = maskOverlap(session.mask(), *reference, referenceLabel).dice();
        }
        steps.push_back(std::move(j));
    }
    session.engine().session()->exportAs(output, format);
    nlohmann::ordered_json report;
    report["input"] = input;
    report["output"] = output;
    report["clicks"] = std::move(steps);
    const std::string text = report.dump(2);
    if (const auto file = args.value("report")) {
        writeReport(*file, text);
    }
    std::printf("%s\n", text.c_str());
    return 0;
}

} // namespace steerseg::cli
