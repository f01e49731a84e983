#pragma once

// What the panel offers in the current state, as plain data: the banner, the readouts, the
// parameter rows and every button with the action it emits. panel.cpp draws it with ImGui;
// tests read it to check that every action the workflow offers in a state is reachable by
// touch alone.
#include "model/action.hpp"
#include "workflow/status.hpp"

#include <glm/vec3.hpp>
#include <optional>
#include <string>
#include <vector>

namespace steerseg::ui {

// What a button asks of the operator before its action can go: nothing (a tap sends it), a
// name typed on the on-screen keyboard, or a colour tapped among the swatches. The action is
// then only the pattern (the structure it names) the panel completes and sends from there.
// `Form`: a button of the panel's own PACS search form (a field, a date chip): the panel acts
// on it and no action goes.
enum class Completion { None, Name, Colour, Form };

struct PanelButton {
    std::string label; // unique within the panel (it is the widget's id)
    model::Action action;
    bool active = false; // drawn highlighted (a toggle that is on, the selected preset)
    bool enabled = true; // drawn greyed out and inert (Undo with nothing to undo)
    Completion completion = Completion::None;
    std::optional<glm::dvec3> swatch = std::nullopt; // drawn in this colour (r g b within 0..1)
};

// The panel's own editors that change what it offers (ui/structure_editing, ui/pacs_form).
struct PanelEditors {
    bool rename = false;           // the keyboard is open for the active structure's name
    bool colours = false;          // the palette's swatches are shown for the active structure
    model::PacsKeys pacsKeys = {}; // what the PACS search form holds
    std::string pacsPeer = {};     // the query peer the form has chosen ("" = the first)
};

// The load screen's PACS search (Status::pacs; docs/dicom-network.md "The kiosk's search").
// The fields and chips change only the form (PacsForm); Search, a result's Retrieve and
// Cancel are actions.
struct PacsField {
    model::SearchField field = model::SearchField::PatientId;
    std::string label; // "Patient ID: 12345##pacs_patient_id": a tap opens the keyboard
};
struct PacsChip {
    std::string preset; // model::datePresetName
    std::string label;  // "Last 7 days##pacs_date_last_7_days"
    bool chosen = false;
};
// Where the site has more than one query peer: which one Search asks (the first by default).
struct PacsPeerChoice {
    std::string name;  // a [[dicom.peers]] name with query = true
    std::string label; // "archive##pacs_peer_archive"
    bool chosen = false;
};
struct PacsPanel {
    std::vector<PacsPeerChoice> peers; // empty with one query peer: no choice to make
    std::vector<PacsField> fields;
    std::vector<PacsChip> dates; // where the site has study_date among its fields
    // SearchPacs with the form's keys to the chosen peer (disabled while one runs).
    PanelButton search;
    std::string searchLine; // "searching...", "3 studies on pacs", or why it failed
    // Each study found: RetrievePacs of the whole study (disabled while a retrieve runs) and,
    // beside it, Series (ListPacsSeries; active while its series are listed), both to the peer
    // the study was found on.
    std::vector<PanelButton> results;
    std::vector<PanelButton> seriesOf;
    // The series of one of them (`seriesStudy`: its index in `results`, listed under it): the
    // listing's line while it runs or how it ended, and RetrievePacs of each series alone
    // ("Retrieve CT #3 Chest 1 mm (60 images)"; disabled while a retrieve runs).
    std::optional<std::size_t> seriesStudy;
    std::string seriesLine;
    std::vector<PanelButton> series;
    // While a retrieve runs, and after it: images received of those expected (the bar: -1
    // while the PACS has not said how many), the line, and Cancel while it runs.
    std::optional<double> progress;
    std::string progressText; // "12 of 60 images"
    std::string retrieveLine;
    std::optional<PanelButton> cancel;
};

// A steerable parameter: tapping its name selects it for the knob (SelectParam), -/+ nudge it
// by one fine step (NudgeParam), the slider sets it (SetParam).
struct ParamRow {
    model::Param param = model::Param::T;
    std::string label; // "T", "eps", "alpha", "brush"
    double value = 0.0;
    workflow::ParamRange range;
    bool selected = false;
};

// Window/level sliders (Inspect): SetWindow.
struct WindowRow {
    double level = 0.0;
    double width = 1.0;
    double min = 0.0; // the scan's value range, for the sliders' ends
    double max = 1.0;
};

struct Readout {
    std::string label;
    std::string value;
};

struct PanelModel {
    std::string banner; // the state, in the operator's words (the large state readout)
    std::string scanName;
    std::string hint; // what to do next
    std::string message;
    bool error = false;
    // The audit log cannot be written: shown above all else until it can ("" = it can).
    std::string auditAlarm;
    // A speed is off because this GPU computed it wrong at start-up: shown all along ("" = none).
    std::string gpuAlarm;
    std::optional<double> progress; // Loading: 0..1, < 0 when unknown
    std::vector<Readout> readouts;
    std::vector<ParamRow> params;
    std::optional<WindowRow> window;
    std::vector<PanelButton> scans; // LoadScan, one per scan
    // The DICOM node's (Status::received): LoadScan of each received series, newest first; one
    // still arriving is greyed out. The note announces one that has just come.
    std::vector<PanelButton> received;
    std::string receivedNote;
    std::vector<std::string> outbox; // what waits to be sent to the PACS, and why
    // The PACS search form and its results (the load screen; elsewhere only a retrieve's
    // progress and Cancel); nullopt without a peer to query.
    std::optional<PacsPanel> pacs;
    std::vector<PanelButton> presets; // ApplyPreset
    std::vector<PanelButton> speeds;  // SetSpeed: threshold, edge, classify (the chosen one active)
    // Classify chosen: the outside-mode toggle and Clear examples, the counts in `examples`,
    // and `speedNote` while the classifier waits for an example of each kind.
    std::vector<PanelButton> exampleTools;
    std::string examples; // "2 inside, 1 outside" ("" unless classify is chosen)
    std::string speedNote;
    // Run/Pause, erase mode, box mode and Clear box, Undo, Redo, Restart, Export ...
    std::vector<PanelButton> tools;
    std::vector<PanelButton> views; // ShowSlices
    // The session's structures, three buttons each: select it (its name and volume; the active
    // one highlighted), hide or show it, delete it. Then one button per site structure not in
    // the session yet, and a free "Structure N": add it.
    std::vector<PanelButton> structures;
    std::vector<PanelButton> newStructures;
    // The active structure's Rename (Completion::Name) and Colour (Completion::Colour, drawn in
    // its colour); while the swatches are open, one Recolour a palette colour.
    std::vector<PanelButton> structureTools;
    std::vector<PanelButton> colours;
    // Review: each structure's figures (docs/measurements.md), formatted for the table.
    struct MeasurementRow {
        std::string name;
        std::string volume;  // "1530.2 ml"
        std::string axes;    // RECIST long x short axis on the axial slice: "112.4 x 80.1 mm"
        std::string longest; // the longest 3D diameter: "140.3 mm"
        std::string values;  // mean +- sd in the scan's units: "54 +- 12 HU"
    };
    std::vector<MeasurementRow> measurements;
    std::vector<PanelButton> nav; // Back, Proceed (labelled for the state), Dismiss
    std::vector<Readout> devices; // the controllers: name, "connected" or "disconnected"
};

// `scans`: what the Load list offers ("builtin:sample" and the paths the kiosk passes in).
PanelModel buildPanelModel(const workflow::Status& status, const std::vector<std::string>& scans,
                           const PanelEditors& editors = {});

// The structures section of the panel (PanelModel::structures and newStructures).
void addStructures(const workflow::Status& st, const PanelEditors& open, PanelModel& m);

// The PACS section of the panel (PanelModel::pacs): `loadScreen` where the scans are listed.
// `peer`: the form's choice among view.peers ("" or one no longer offered: the first).
std::optional<PacsPanel> buildPacsPanel(const workflow::PacsView& view, const model::PacsKeys& keys,
                                        const std::string& peer, bool loadScreen);
// A series row's words: "CT  #3  Chest 1 mm  (60 images)" (what the PACS did not say left out).
std::string pacsSeriesLabel(const workflow::PacsSeries& series);

// Every action a touch on the panel can emit (enabled buttons that need no completion, and for
// each parameter row SelectParam, NudgeParam -1/+1 and SetParam at its ends; SetWindow for the
// window row).
std::vector<model::Action> reachableActions(const PanelModel& model);

// The operator's words for a state ("Seeding") and a parameter ("T", "brush"), and the label of the
// Proceed button in a state ("Seed", "Run", "Review", "Export"; empty where Proceed means
// nothing).
std::string stateLabel(model::State state);
std::string paramLabel(model::Param param);
// "Threshold", "Edge", "Classify": the speed buttons' words.
std::string speedLabel(model::SpeedKind kind);
std::string proceedLabel(model::State state);
// A scan's name for its button: the file or folder name, "Sample" for builtin:sample.
std::string scanLabel(const std::string& path);

} // namespace steerseg::ui
