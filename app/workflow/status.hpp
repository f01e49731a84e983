#pragma once

// Everything the screen shows about the workflow, as one plain value the UI reads each frame.
#include "model/action.hpp"
#include "workflow/engine.hpp"

#include <array>
#include <string>
#include <vector>

namespace steerseg::workflow {

struct ParamRange {
    double min = 0.0;
    double max = 1.0;
    double fineStep = 0.01; // one knob detent or key press
};

// The view state the kiosk turns into render::ViewParams.
struct ViewState {
    double yawDeg = 0.0; // 3D camera about the scan's centre; 0,0 = anterior view
    double pitchDeg = 0.0;
    double zoom = 1.0;
    glm::ivec3 slice{-1}; // per model::SliceAxis (axial, coronal, sagittal); -1 = middle
    model::SliceAxis first = model::SliceAxis::Axial;    // the slice view with the yellow contour
    model::SliceAxis second = model::SliceAxis::Coronal; // the slice view with the speed
    double windowLevel = 0.0;
    double windowWidth = 0.0; // 0 = not set yet: the kiosk's default for the scan
    std::string transfer;     // transfer-function preset name ("" = the scan's default)
};

// A configured input device as the panel lists it. The kiosk fills Status::devices from its
// input hub; the workflow itself knows no devices and leaves the list empty.
struct DeviceLink {
    std::string name; // the config's device name: "shuttle", "pedal"
    std::string kind; // "shuttle", "radial", "powermate", "gpio_input", "gpio_led"
    bool connected = false;
};

// A series the kiosk's DICOM node has received, for the load screen. The kiosk fills
// Status::received from its incoming store; the workflow knows no network and leaves it empty.
struct ReceivedScan {
    std::string path;      // the series' folder: what LoadScan opens
    std::string label;     // one line: modality, study date, patient, description, image count
    bool arriving = false; // images came a moment ago: more may follow, not offered yet
};

// One study a PACS search found, for the load screen's results list.
struct PacsStudy {
    std::string studyUid; // what RetrievePacs names
    std::string label;    // one line: date, patient, ID, modalities, description, image count
};

// One series of a study a PACS listing found, for the load screen's series rows.
struct PacsSeries {
    std::string seriesUid; // what RetrievePacs names beside its study
    std::string modality;
    std::string number; // SeriesNumber as the PACS gives it ("" when it did not)
    std::string description;
    int images = -1; // -1: the PACS did not say
};

// The kiosk's PACS search and retrieve (docs/dicom-network.md "The kiosk's search"), filled by
// its DICOM node like `received`; the workflow leaves it empty. Counters only grow, so that a
// script can wait for the next search or retrieve to end.
struct PacsView {
    std::vector<std::string> peers;       // [[dicom.peers]] with query = true; empty: no search
    std::vector<std::string> fields;      // the form's fields ([dicom] search_fields), in order
    std::vector<std::string> datePresets; // the date chips ([dicom] search_date_presets)
    bool searching = false;
    int searches = 0;       // searches ended (found, failed or refused)
    std::string searchLine; // how the last one ended: "3 studies on pacs", or why not
    std::vector<PacsStudy> studies;
    std::string studiesPeer; // the peer they were found on: their series and retrieve ask it
    // The series of one study (ListPacsSeries): while listed, how the last listing ended, the
    // study and peer it asked, and the series found.
    bool listingSeries = false;
    int seriesListings = 0; // listings ended (found, failed or refused)
    std::string seriesLine; // "2 series of the study on pacs", or why not
    std::string seriesStudyUid;
    std::string seriesPeer;
    std::vector<PacsSeries> series;
    bool retrieving = false;
    int retrieves = 0; // retrieves ended
    // The retrieve under way, or the last one: images stored of those the PACS expects (0
    // until its first response says).
    int received = 0;
    int failed = 0;
    int expected = 0;
    std::string retrieveLine; // "retrieving 12 of 60 images ...", its end, or why it failed
};

// One structure of the session, as the panel lists it.
struct StructureRow {
    model::StructureInfo info;
    double volumeMl = 0.0; // the active one's: the status's own volumeMl
    bool active = false;
    bool empty = true; // no surface yet
};

// A structure's measurements (core/mask_measurements), taken when the workflow enters review.
struct StructureMeasured {
    // Which of the session's structures (its place in the list): a rename or a recolour in
    // review changes the name and colour shown here, not which structure the figures are of.
    std::size_t structure = 0;
    std::string name;
    glm::dvec3 colour{1.0};
    bool visible = true;
    MaskMeasurements measured;
};

struct Status {
    model::State state = model::State::NoScan;
    std::string message; // the last error or notice for the operator ("" = none)
    // Why the audit log cannot be written ("" while it is): the screen shows it until it clears,
    // whatever the message; export waits for AcknowledgeAudit meanwhile.
    std::string auditProblem;
    // Speeds off on this GPU (Settings::speedsOff), and what the screen says about them all
    // along ("" when none is).
    std::vector<model::SpeedKind> speedsOff;
    std::string gpuAlarm;
    bool auditAcknowledged = false;
    double loadProgress = 0.0;
    ScanInfo scan;
    model::LevelSetParams params;
    double radius = 3.0; // brush, voxels
    model::Param selected = model::Param::T;
    std::array<ParamRange, model::kParamCount> ranges{};
    bool eraseMode = false;
    bool outsideMode = false; // a tap marks an outside example (model::MarkOutside)
    // The speed the operator chose, and the one the engine runs: they differ while Classify
    // waits for an inside (probe) and an outside example.
    model::SpeedKind speed = model::SpeedKind::Threshold;
    model::SpeedKind speedInForce = model::SpeedKind::Threshold;
    std::vector<model::Sphere> insideExamples; // voxels, oldest first (at most kMaxExamples)
    std::vector<model::Sphere> outsideExamples;
    // The dabs of painted strokes (model::PaintStroke), oldest first: every one trains classify.
    std::vector<model::Sphere> paintedInside;
    std::vector<model::Sphere> paintedOutside;
    std::optional<model::Box> box; // the operator's box (model::SetBox), drawn in every view
    // Box mode (model::SetBoxMode): a drag on a slice draws the box; and the face a knob
    // detent moves there (none: the knob drives `selected`).
    bool boxMode = false;
    std::optional<model::BoxFace> boxFace;
    bool hasLevelSet = false;
    bool unexported = false; // the level set changed since its last export (a load must wait)
    // What the workflow would accept now, by the transition table (transition_table.hpp) and
    // its guards; an action of another kind is refused. Arguments can still be refused.
    model::ActionKinds allowed;
    int seeds = 0;
    int erasures = 0;
    int iterations = 0;
    double evolvedTime = 0.0;
    double volumeMl = 0.0;
    bool converged = false;
    // Erase runs that grew past Settings::eraseRunGrowth and went back to their erase, since
    // the scan was loaded (docs/steering.md).
    int eraseRunsTakenBack = 0;
    // Erases whose runs withdrew beyond their reach from the start, as one taken back had
    // under the same T, eps, alpha and kind of speed.
    int erasesWithdrawOnly = 0;
    bool canUndo = false;
    bool canRedo = false;
    std::string preset;                     // the last preset applied ("" = none)
    std::string exportedPath;               // Done: where the mask went (the first format's file)
    std::vector<std::string> exportFormats; // what an export writes, in the config's order
    std::vector<std::string> exportedFiles; // Done: every file the last export wrote
    int exports = 0;                        // exports that succeeded: a new one changes it
    ViewState view;
    // The session's structures in order (docs/structures.md); one of them is active.
    std::vector<StructureRow> structures;
    std::vector<std::string> structureKinds; // the site's names (Settings::structureKinds)
    // Review, done: every structure with a surface, measured on entering review (the panel's
    // table, the RECIST lines on the axial view); empty elsewhere.
    std::vector<StructureMeasured> measurements;
    std::vector<std::string> presets; // names, in the config's order
    std::vector<DeviceLink> devices;  // the kiosk's, for the panel (see DeviceLink)
    // The kiosk's DICOM node (docs/dicom-network.md), for the panel; empty without one.
    std::vector<ReceivedScan> received; // newest first
    std::string receivedNote;           // a series that has just arrived ("" = none)
    std::vector<std::string> outbox;    // each object waiting to be sent, and why, one line each
    PacsView pacs;
};

} // namespace steerseg::workflow
