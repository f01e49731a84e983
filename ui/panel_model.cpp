#include "ui/panel_model.hpp"

#include "model/speed_kind.hpp"
#include "model/structure.hpp"
#include "workflow/transition_table.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace steerseg::ui {

namespace {

using model::Action;
using model::ActionKind;
using model::Param;
using model::SliceAxis;
using model::State;

std::string fixed(double value, int decimals) {
    char text[64];
    std::snprintf(text, sizeof text, "%.*f", decimals, value);
    return text;
}

bool scanLoaded(State s) {
    return s != State::NoScan && s != State::Loading;
}

std::string hintFor(State s) {
    switch (s) {
    case State::NoScan:
        return "Choose a scan to load.";
    case State::Loading:
        return "Reading the scan...";
    case State::Inspect:
        return "Tap a slice to probe the tissue, or pick a preset.";
    case State::Seeding:
        return "Tap a slice to place a seed; hold to erase.";
    case State::Evolving:
        return "Growing. Steer with the parameters; tap to add, hold to erase.";
    case State::Paused:
        return "Paused. Steer, then run again or review.";
    case State::Review:
        return "Check the result, then export.";
    case State::Exporting:
        return "Writing the mask...";
    case State::Done:
        return "Exported. Load the next scan.";
    case State::Error:
        return "Something went wrong; dismiss to go on.";
    }
    return {};
}

workflow::ParamRange rangeFor(const workflow::Status& st, Param p) {
    workflow::ParamRange r = st.ranges[static_cast<std::size_t>(p)];
    if (r.max > r.min && std::isfinite(r.min) && std::isfinite(r.max)) {
        return r;
    }
    // The workflow gave no range yet: one that at least spans the scan.
    const double lo = st.scan.minValue;
    const double hi = std::max(st.scan.maxValue, lo + 1.0);
    switch (p) {
    case Param::T:
        return {lo, hi, (hi - lo) / 200.0};
    case Param::Eps:
        return {0.0, hi - lo, (hi - lo) / 400.0};
    case Param::Alpha:
        return {0.0, 1.0, 0.01};
    case Param::Radius:
        return {1.0, 30.0, 0.5};
    }
    return r;
}

double valueOf(const workflow::Status& st, Param p) {
    switch (p) {
    case Param::T:
        return static_cast<double>(st.params.T);
    case Param::Eps:
        return static_cast<double>(st.params.eps);
    case Param::Alpha:
        return static_cast<double>(st.params.alpha);
    case Param::Radius:
        return st.radius;
    }
    return 0.0;
}

const char* axisName(SliceAxis a) {
    switch (a) {
    case SliceAxis::Axial:
        return "Axial";
    case SliceAxis::Coronal:
        return "Coronal";
    case SliceAxis::Sagittal:
        return "Sagittal";
    }
    return "?";
}

void addReadouts(const workflow::Status& st, PanelModel& m) {
    const std::string units = st.scan.units.empty() ? "" : " " + st.scan.units;
    m.readouts.push_back({"T", fixed(static_cast<double>(st.params.T), 1) + units});
    m.readouts.push_back({"eps", fixed(static_cast<double>(st.params.eps), 1) + units});
    m.readouts.push_back({"alpha", fixed(static_cast<double>(st.params.alpha), 2)});
    m.readouts.push_back({"iter", std::to_string(st.iterations)});
    m.readouts.push_back({"time", fixed(st.evolvedTime, 1)});
    m.readouts.push_back({"ml", fixed(st.volumeMl, 2)});
    m.readouts.push_back({"done", st.converged ? "yes" : "no"});
}

// The speed is steered like a parameter: the same states, live while evolving. The examples
// matter only to classify, so its tools appear only when it is chosen.
void addSpeed(const workflow::Status& st, PanelModel& m) {
    for (model::SpeedKind k : model::kSpeedKinds) {
        if (std::find(st.speedsOff.begin(), st.speedsOff.end(), k) != st.speedsOff.end()) {
            continue; // this GPU computes it wrong (Status::gpuAlarm says so)
        }
        m.speeds.push_back({speedLabel(k) + "##speed", model::SetSpeed{k}, st.speed == k});
    }
    if (st.speed != model::SpeedKind::Classify) {
        return;
    }
    const std::size_t inside = st.insideExamples.size();
    const std::size_t outside = st.outsideExamples.size();
    m.examples = std::to_string(inside) + " inside, " + std::to_string(outside) + " outside";
    const std::size_t paintedIn = st.paintedInside.size();
    const std::size_t paintedOut = st.paintedOutside.size();
    if (paintedIn + paintedOut > 0) {
        m.examples += "; painted or corrected " + std::to_string(paintedIn) + " inside, " +
                      std::to_string(paintedOut) + " outside spheres";
    }
    m.exampleTools.push_back({st.outsideMode ? "Outside: on" : "Outside: off",
                              model::SetOutsideMode{!st.outsideMode}, st.outsideMode});
    m.exampleTools.push_back({"Clear examples", model::ClearExamples{}, false,
                              st.allowed.contains(model::ActionKind::ClearExamples)});
    if (st.speedInForce != model::SpeedKind::Classify) {
        std::string needs;
        if (inside + paintedIn == 0) {
            needs = "an inside example (a probe or a seed)";
        }
        if (outside + paintedOut == 0) {
            needs += std::string(needs.empty() ? "" : " and ") + "an outside example";
        }
        m.speedNote = "Classify needs " + needs + "; " +
                      std::string(model::speedKindName(st.speedInForce)) + " runs until then.";
    }
}

} // namespace

PanelModel buildPanelModel(const workflow::Status& st, const std::vector<std::string>& scans,
                           const PanelEditors& editors) {
    PanelModel m;
    for (const workflow::DeviceLink& d : st.devices) {
        m.devices.push_back({d.name, d.connected ? "connected" : "disconnected"});
    }
    const State s = st.state;
    // Which controls a state shows follows the workflow's table (offered: a button such as Run
    // before a seed is there to explain its refusal); whether one works now, Status::allowed.
    const model::ActionKinds offered = workflow::offeredActions(s);
    // The brush and the erase toggle belong where a tap on a slice places and erases spheres.
    const bool spheres = offered.contains(ActionKind::Erase);
    // The box (docs/ui.md): drawn by a drag in box mode where the table lets it be set.
    const bool boxes = offered.contains(ActionKind::SetBox);
    m.banner = stateLabel(s);
    m.hint = hintFor(s);
    if (boxes && st.boxMode) {
        m.hint = "Drag on a slice to draw the box; drag its edge to move a face, then turn a "
                 "knob to move that face.";
    }
    // The export screen says what Export will write, as the config enables it.
    if ((s == State::Review || s == State::Done) && !st.exportFormats.empty()) {
        std::string formats;
        for (const std::string& f : st.exportFormats) {
            formats += (formats.empty() ? "." : ", .") + f;
        }
        m.hint += " Export writes " + formats + ".";
    }
    m.message = st.message;
    m.receivedNote = st.receivedNote;
    m.outbox = st.outbox;
    m.error = s == State::Error;
    if (!st.auditProblem.empty()) {
        m.auditAlarm =
            "AUDIT LOG NOT WRITTEN: " + st.auditProblem +
            (st.auditAcknowledged ? ". Acknowledged: exports are recorded once it can be written."
                                  : ". Export waits for an acknowledgement.");
    }
    m.gpuAlarm = st.gpuAlarm;
    if (s == State::Done && !st.exportedPath.empty() && m.message.empty()) {
        m.message = "Saved to " + st.exportedPath;
    }
    if (s == State::Loading) {
        m.progress = st.loadProgress;
    }
    if (scanLoaded(s) && s != State::Error) {
        m.scanName = st.scan.name;
        addReadouts(st, m);
    }

    // The start, inspect and done screens list the scans.
    if (offered.contains(ActionKind::LoadScan) &&
        (s == State::NoScan || s == State::Inspect || s == State::Done)) {
        for (std::size_t i = 0; i < scans.size(); ++i) {
            // The index keeps two scans of the same file name apart as widgets.
            m.scans.push_back({"Load " + scanLabel(scans[i]) + "##scan" + std::to_string(i),
                               model::LoadScan{scans[i]}});
        }
        for (std::size_t i = 0; i < st.received.size(); ++i) {
            const workflow::ReceivedScan& r = st.received[i];
            m.received.push_back({r.label + "##received" + std::to_string(i),
                                  model::LoadScan{r.path}, false, !r.arriving});
        }
    }
    m.pacs = buildPacsPanel(st.pacs, editors.pacsKeys, editors.pacsPeer,
                            offered.contains(ActionKind::LoadScan) &&
                                (s == State::NoScan || s == State::Inspect || s == State::Done));

    if (offered.contains(ActionKind::SetParam)) {
        std::vector<Param> shown{Param::T, Param::Eps, Param::Alpha};
        if (spheres) {
            shown.push_back(Param::Radius);
        }
        for (Param p : shown) {
            ParamRow row;
            row.param = p;
            row.label = paramLabel(p);
            row.value = valueOf(st, p);
            row.range = rangeFor(st, p);
            row.selected = st.selected == p;
            m.params.push_back(row);
        }
        for (const std::string& preset : st.presets) {
            // The suffix keeps a preset named like a button ("Undo") a widget of its own.
            m.presets.push_back(
                {preset + "##preset", model::ApplyPreset{preset}, preset == st.preset});
        }
    }

    if (offered.contains(ActionKind::SetSpeed)) {
        addSpeed(st, m);
    }

    if (s == State::Inspect) {
        WindowRow w;
        w.min = st.scan.minValue;
        w.max = std::max(st.scan.maxValue, st.scan.minValue + 1.0);
        w.width = st.view.windowWidth > 0.0 ? st.view.windowWidth : w.max - w.min;
        w.level = st.view.windowWidth > 0.0 ? st.view.windowLevel : 0.5 * (w.min + w.max);
        m.window = w;
    }

    if (spheres) {
        // In Seeding the forward button runs (below); one Run button, not two.
        if (s == State::Evolving) {
            m.tools.push_back({"Pause", model::Pause{}});
        } else if (s == State::Paused) {
            m.tools.push_back({"Run", model::Run{}});
        }
        m.tools.push_back({st.eraseMode ? "Erase: on" : "Erase: off",
                           model::SetEraseMode{!st.eraseMode}, st.eraseMode});
    }
    if (boxes) {
        m.tools.push_back({st.boxMode ? "Box: on" : "Box: off",
                           model::SetBoxMode{!st.boxMode, std::nullopt}, st.boxMode});
        if (st.box) {
            m.tools.push_back(
                {"Clear box", model::ClearBox{}, false, st.allowed.contains(ActionKind::ClearBox)});
        }
    }
    if (offered.contains(ActionKind::Undo)) {
        m.tools.push_back({"Undo", model::Undo{}, false, st.allowed.contains(ActionKind::Undo)});
        m.tools.push_back({"Redo", model::Redo{}, false, st.allowed.contains(ActionKind::Redo)});
    }
    if (spheres) {
        m.tools.push_back(
            {"Restart", model::Restart{}, false, st.allowed.contains(ActionKind::Restart)});
    }
    if (s == State::Done) {
        m.tools.push_back({"Export again", model::Export{}});
    }

    if (offered.contains(ActionKind::EditStructure)) {
        addStructures(st, editors, m);
    }
    for (const workflow::StructureMeasured& measured : st.measurements) {
        const MaskMeasurements& f = measured.measured;
        char volume[32];
        char axes[48];
        char longest[32];
        char values[64];
        std::snprintf(volume, sizeof volume, "%.1f ml", f.volumeMl);
        std::snprintf(axes, sizeof axes, "%.1f x %.1f mm", f.axial.longest.lengthMm,
                      f.axial.perpendicular.lengthMm);
        std::snprintf(longest, sizeof longest, "%.1f mm", f.longest3d.lengthMm);
        std::snprintf(values, sizeof values, "%.0f +- %.0f %s", f.intensity.mean, f.intensity.sd,
                      st.scan.units.c_str());
        m.measurements.push_back({measured.name, volume, axes, longest, values});
    }

    // The error and export screens keep to their message.
    if (offered.contains(ActionKind::ShowSlices) && s != State::Exporting && s != State::Error) {
        for (int view = 0; view < 2; ++view) {
            for (SliceAxis a : {SliceAxis::Axial, SliceAxis::Coronal, SliceAxis::Sagittal}) {
                model::ShowSlices show{st.view.first, st.view.second};
                (view == 0 ? show.first : show.second) = a;
                const bool current = (view == 0 ? st.view.first : st.view.second) == a;
                m.views.push_back({std::string(axisName(a)) + "##view" + std::to_string(view + 1),
                                   show, current});
            }
        }
    }

    if (s == State::Error) {
        m.nav.push_back({"Dismiss", model::Dismiss{}});
    }
    if (st.allowed.contains(ActionKind::AcknowledgeAudit)) {
        m.nav.push_back({"Acknowledge: no audit log", model::AcknowledgeAudit{}});
    }
    if (offered.contains(ActionKind::Back)) {
        const char* label = s == State::Review ? "Back: steer"
                            : s == State::Done ? "Back: review"
                                               : "Back";
        m.nav.push_back({label, model::Back{}});
    }
    if (s == State::Seeding) {
        m.nav.push_back({"Run", model::Run{}});
    } else if (offered.contains(ActionKind::Proceed) && !proceedLabel(s).empty()) {
        m.nav.push_back({proceedLabel(s) + "##proceed", model::Proceed{}});
    }
    return m;
}

std::vector<Action> reachableActions(const PanelModel& m) {
    std::vector<Action> out;
    for (const auto* list :
         {&m.scans, &m.received, &m.presets, &m.speeds, &m.exampleTools, &m.tools, &m.views,
          &m.structures, &m.newStructures, &m.structureTools, &m.colours, &m.nav}) {
        for (const PanelButton& b : *list) {
            if (b.enabled && b.completion == Completion::None) {
                out.push_back(b.action);
            }
        }
    }
    for (const ParamRow& row : m.params) {
        out.emplace_back(model::SelectParam{row.param});
        out.emplace_back(model::NudgeParam{row.param, -1.0});
        out.emplace_back(model::NudgeParam{row.param, 1.0});
        out.emplace_back(model::SetParam{row.param, row.range.min});
        out.emplace_back(model::SetParam{row.param, row.range.max});
    }
    if (m.window) {
        out.emplace_back(model::SetWindow{m.window->level, m.window->width});
    }
    if (m.pacs) {
        std::vector<PanelButton> pacs = m.pacs->results;
        pacs.insert(pacs.end(), m.pacs->seriesOf.begin(), m.pacs->seriesOf.end());
        pacs.insert(pacs.end(), m.pacs->series.begin(), m.pacs->series.end());
        if (!m.pacs->fields.empty()) {
            pacs.push_back(m.pacs->search);
        }
        if (m.pacs->cancel) {
            pacs.push_back(*m.pacs->cancel);
        }
        for (const PanelButton& b : pacs) {
            if (b.enabled) {
                out.push_back(b.action);
            }
        }
    }
    return out;
}

} // namespace steerseg::ui
