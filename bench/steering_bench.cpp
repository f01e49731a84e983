// The clicks protocol (docs/steering.md): a robot operator corrects the product's segmentation
// of one scan towards its expert label, through the kiosk's own workflow and engine
// (engine::ClickSession, the code `segment --click` runs), and in the same run the paint-only
// baseline: the same robot with each click painted as a sphere of the same radius, no solver.
//   steering_bench --input SCAN --reference LABEL [--reference-label N] [--clicks N] [--box]
//                  [--paint-only] [--max-iterations N] [--config FILE] [--nsd-mm T]
//                  [--masks DIR] --report R.json
// --box: the challenge's protocol, the label's box first and each correction where the
// challenge's evaluation clicks (the error's centre in voxel steps: bench::DepthMeasure).
// The report: {"clicks": [...], "baseline": {"clicks": [...]}, "summary": {...}}, one entry a
// click (0: the initial prompt) with its kind, voxel, radius, Dice, normalised surface Dice,
// seconds from the click to the solver's stop and to its first visible change (and where the
// latter went: undo snapshots, the edit, the speed's training, the volume count), stop reason.
// The summary: Dice initially and after 5 and 10, its AUC over 6 steps, and the interactive
// challenge's own scores after 5 corrections (dsc_auc, nsd_auc, final_dsc, final_nsd,
// total_seconds; bench::challengeScores). --masks writes the level set's mask after each step
// as DIR/stepNN.u8 (one byte a voxel, the scan's storage order), to see what a step moved.
#include "config/config_loader.hpp"
#include "core/mask_overlap.hpp"
#include "engine/click_session.hpp"
#include "files/file_write.hpp"
#include "kiosk/settings_from_config.hpp"
#include "platform/egl/offscreen_context.hpp"
#include "scan/scan_reader.hpp"
#include "steering/click_robot.hpp"

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <nlohmann/json.hpp>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

namespace {

using namespace steerseg;
using Json = nlohmann::ordered_json;

struct Options {
    std::string input;
    std::string reference;
    int label = -1;
    int clicks = 10;
    bool paintOnly = false;
    bool box = false; // the challenge's protocol: the label's bounding box first, then clicks
    int maxIterations = 3000;
    std::string config;
    double nsdMm = 2.0;
    std::string report;
    std::string masks;
};

Options parse(int argc, char** argv) {
    Options o;
    for (int a = 1; a < argc; ++a) {
        const std::string name = argv[a];
        if (name == "--paint-only" || name == "--box") {
            (name == "--box" ? o.box : o.paintOnly) = true;
            continue;
        }
        if (a + 1 >= argc) {
            throw std::invalid_argument(name + " needs a value");
        }
        const std::string value = argv[++a];
        if (name == "--input") {
            o.input = value;
        } else if (name == "--reference") {
            o.reference = value;
        } else if (name == "--reference-label") {
            o.label = std::stoi(value);
        } else if (name == "--clicks") {
            o.clicks = std::stoi(value);
        } else if (name == "--max-iterations") {
            o.maxIterations = std::stoi(value);
        } else if (name == "--config") {
            o.config = value;
        } else if (name == "--nsd-mm") {
            o.nsdMm = std::stod(value);
        } else if (name == "--report") {
            o.report = value;
        } else if (name == "--masks") {
            o.masks = value;
        } else {
            throw std::invalid_argument("unknown option " + name);
        }
    }
    if (o.input.empty() || o.reference.empty() || o.report.empty()) {
        throw std::invalid_argument("give --input, --reference and --report");
    }
    if (o.clicks < 0 || o.clicks > 100 || o.maxIterations < 1) {
        throw std::invalid_argument("--clicks 0..100, --max-iterations >= 1");
    }
    // Checked before the runs, which take minutes, rather than at the first mask written.
    if (!o.masks.empty() && !std::filesystem::is_directory(o.masks)) {
        throw std::invalid_argument("--masks " + o.masks + ": no such folder");
    }
    return o;
}

void paintBox(const bench::MaskGrid& grid, std::vector<std::uint8_t>& mask,
              const bench::VoxelBox& box) {
    for (int k = box.lo.z; k <= box.hi.z; ++k) {
        for (int j = box.lo.y; j <= box.hi.y; ++j) {
            for (int i = box.lo.x; i <= box.hi.x; ++i) {
                mask[static_cast<std::size_t>(i) +
                     static_cast<std::size_t>(grid.dims.x) *
                         (static_cast<std::size_t>(j) +
                          static_cast<std::size_t>(grid.dims.y) * static_cast<std::size_t>(k))] = 1;
            }
        }
    }
}

const char* kindOf(int click, bool positive) {
    return click == 0 ? "initial" : (positive ? "positive" : "negative");
}

Json entry(int click, const bench::RobotClick& c, double radius,
           const std::vector<std::uint8_t>& mask, double dice, double nsd) {
    Json j;
    j["click"] = click;
    j["kind"] = kindOf(click, c.positive);
    j["voxel"] = {c.voxel.x, c.voxel.y, c.voxel.z};
    j["radius"] = radius;
    j["depth_mm"] = c.depthMm;
    j["component_voxels"] = c.componentVoxels;
    j["mask_voxels"] =
        std::count_if(mask.begin(), mask.end(), [](std::uint8_t v) { return v != 0; });
    j["dice"] = dice;
    j["nsd"] = nsd;
    return j;
}

Json summary(const std::vector<double>& dices, const std::vector<double>& nsds,
             double totalSeconds) {
    Json s;
    const auto after = [&dices](std::size_t k) -> Json {
        return dices.empty() ? Json(nullptr) : Json(dices[std::min(k, dices.size() - 1)]);
    };
    s["dice_initial"] = after(0);
    s["dice_after_5"] = after(5);
    s["dice_after_10"] = after(10);
    s["dice_auc_6"] = bench::diceAuc(dices);
    // The interactive challenge's own scores after five corrections (issue 51).
    const bench::ChallengeScores c = bench::challengeScores(dices, nsds);
    s["dsc_auc"] = c.dscAuc;
    s["nsd_auc"] = c.nsdAuc;
    s["final_dsc"] = c.finalDsc;
    s["final_nsd"] = c.finalNsd;
    s["total_seconds"] = totalSeconds; // the initial prompt's and five corrections' runs
    return s;
}

Json boxJson(const bench::VoxelBox& b) {
    return {b.lo.x, b.lo.y, b.lo.z, b.hi.x, b.hi.y, b.hi.z};
}

// The robot's loop; `act` answers a prompt (a click, or with a box its step 0: `c` null) and
// returns the mask that follows, adding the product's own figures to `extra`.
template <typename Act>
Json robot(const bench::MaskGrid& grid, const std::vector<std::uint8_t>& label, const Options& o,
           double maxRadius, const std::optional<bench::VoxelBox>& box, Act&& act) {
    Json clicks = Json::array();
    std::vector<double> dices;
    std::vector<double> nsds;
    double totalSeconds = 0.0;
    std::optional<bench::RobotClick> c;
    if (!box) {
        c = bench::initialClick(grid, label);
    }
    for (int n = 0; (c || (box && n == 0)) && n <= o.clicks; ++n) {
        const bool boxStep = box && n == 0;
        const double radius = boxStep ? 0.0 : bench::brushRadius(grid, *c, maxRadius);
        Json extra = Json::object();
        const std::vector<std::uint8_t> mask = act(n, boxStep ? nullptr : &*c, radius, extra);
        const double d = bench::dice(mask, label);
        const double nsd = bench::surfaceDice(grid, mask, label, o.nsdMm);
        Json j;
        if (boxStep) {
            j["click"] = n;
            j["kind"] = "box";
            j["box"] = boxJson(*box);
            j["mask_voxels"] =
                std::count_if(mask.begin(), mask.end(), [](std::uint8_t v) { return v != 0; });
            j["dice"] = d;
            j["nsd"] = nsd;
        } else {
            j = entry(n, *c, radius, mask, d, nsd);
        }
        j.update(extra);
        if (n <= 5 && extra.contains("seconds")) {
            totalSeconds += extra["seconds"].get<double>();
        }
        const glm::ivec3 at = boxStep ? box->lo : c->voxel;
        std::fprintf(stderr, "  click %2d %-8s (%d, %d, %d) r %.1f: Dice %.3f%s\n", n,
                     boxStep ? "box" : kindOf(n, c->positive), at.x, at.y, at.z, radius, d,
                     extra.contains("stop_reason")
                         ? (" " + extra["stop_reason"].get<std::string>() + " " +
                            std::to_string(extra["seconds"].get<double>()) + " s")
                               .c_str()
                         : "");
        clicks.push_back(std::move(j));
        dices.push_back(d);
        nsds.push_back(nsd);
        // The challenge's protocol clicks where the challenge's evaluation would.
        c = bench::correctionClick(grid, mask, label,
                                   box ? bench::DepthMeasure::VoxelSteps
                                       : bench::DepthMeasure::Millimetres);
    }
    Json out;
    out["clicks"] = std::move(clicks);
    out["summary"] = summary(dices, nsds, totalSeconds);
    return out;
}

int run(const Options& o) {
    const scan::LoadedScan reference = scan::readScan(o.reference);
    const Geometry geometry = reference.volume.geometry();
    const bench::MaskGrid grid{geometry.dims, geometry.spacing};
    const std::vector<std::uint8_t> label = referenceVoxels(reference.volume, o.label);
    // The workflow's brush range (param_ranges.cpp): at most half the smallest side.
    const double maxRadius =
        std::max(1.0, std::min({geometry.dims.x, geometry.dims.y, geometry.dims.z}) / 2.0);

    std::optional<bench::VoxelBox> box;
    if (o.box) {
        box = bench::labelBox(grid, label);
        if (!box) {
            throw std::runtime_error("the reference label is empty: no box to start from");
        }
    }

    std::fprintf(stderr, "paint only:\n");
    std::vector<std::uint8_t> painted(grid.count(), 0);
    Json baseline = robot(grid, label, o, maxRadius, box,
                          [&](int, const bench::RobotClick* c, double radius, Json&) {
                              if (c == nullptr) {
                                  // Paint only's answer to a box: the box, filled.
                                  paintBox(grid, painted, *box);
                              } else {
                                  bench::paintSphere(grid, painted, glm::dvec3(c->voxel), radius,
                                                     c->positive ? 1 : 0);
                              }
                              return painted;
                          });
    Json report;
    report["input"] = o.input;
    report["reference"] = o.reference;
    report["reference_label"] = o.label;
    report["nsd_tolerance_mm"] = o.nsdMm;
    report["box"] = box ? boxJson(*box) : Json(nullptr);
    if (o.paintOnly) {
        report["clicks"] = baseline["clicks"];
        report["summary"] = baseline["summary"];
    } else {
        config::KioskConfig cfg = config::defaultConfig();
        if (!o.config.empty()) {
            const config::LoadedConfig loaded =
                config::loadConfig({{o.config, true}}, model::isBindable);
            for (const config::ConfigProblem& p : loaded.problems) {
                std::cerr << "config: " << config::describe(p) << '\n';
            }
            cfg = loaded.config;
        }
        auto context = platform::createOffscreenContext();
        engine::ClickSession session(
            o.input, kiosk::workflowSettings(cfg),
            {cfg.speed.smoothIterations, cfg.speed.conductanceFactor, cfg.speed.kappaFactor});
        if (session.scan().dims() != geometry.dims) {
            throw std::runtime_error("the reference is not on the scan's grid");
        }
        std::fprintf(stderr, "level set:\n");
        Json steered = robot(
            grid, label, o, maxRadius, box,
            [&](int step, const bench::RobotClick* c, double radius, Json& extra) {
                const model::Action prompt =
                    c == nullptr
                        ? model::Action(model::SetBox{model::Box{box->lo, box->hi}})
                        : model::Action(model::Correct{glm::dvec3(c->voxel), c->positive, radius});
                const engine::ClickOutcome r = session.apply(prompt, o.maxIterations);
                extra["seconds"] = r.seconds;
                extra["first_change_seconds"] = r.firstChangeSeconds;
                extra["taken_back"] = r.takenBack;
                extra["withdraw_only"] = r.withdrawOnly;
                const engine::WorkSeconds& w = r.firstChangeWork;
                extra["first_change_breakdown"] = {{"snapshot", w.snapshot},
                                                   {"edit", w.edit},
                                                   {"speed", w.speed},
                                                   {"count", w.count},
                                                   {"other", r.firstChangeSeconds - w.total()}};
                // GPU memory undo holds after the click (its snapshots' copies).
                extra["undo_gpu_bytes"] = session.engine().undoGpuBytes();
                extra["stop_reason"] = r.stopReason;
                if (!r.leakWatch.empty()) {
                    extra["leak_watch"] = r.leakWatch;
                }
                extra["iterations"] = r.iterations;
                extra["T"] = r.T;
                extra["eps"] = r.eps;
                extra["barriers"] = r.barriers;
                if (c == nullptr) {
                    // What the product took from the box as the structure (its seed's probe and
                    // the places that read its tissue): the peer starts from the same spheres.
                    const workflow::Status& st = session.workflow().status();
                    Json inside = Json::array();
                    for (const auto* list : {&st.insideExamples, &st.paintedInside}) {
                        for (const model::Sphere& e : *list) {
                            inside.push_back({e.centre.x, e.centre.y, e.centre.z, e.radius});
                        }
                    }
                    extra["box_inside"] = std::move(inside);
                }
                std::vector<std::uint8_t> mask = session.mask();
                if (!o.masks.empty()) {
                    char name[32];
                    std::snprintf(name, sizeof name, "/step%02d.u8", step);
                    files::writeFileAtomically(o.masks + name, {std::as_bytes(std::span(mask))});
                }
                return mask;
            });
        report["clicks"] = steered["clicks"];
        report["summary"] = steered["summary"];
        report["baseline"] = baseline;
    }
    const std::string text = report.dump(2) + "\n";
    files::writeFileAtomically(o.report, {std::as_bytes(std::span(text.data(), text.size()))});
    std::printf("%s\n", report["summary"].dump().c_str());
    return 0;
}

} // namespace

int main(int argc, char** argv) {
    try {
        return run(parse(argc, argv));
    } catch (const std::exception& e) {
        std::fprintf(stderr, "steering_bench: %s\n", e.what());
        return 1;
    }
}
