#include "model/speed_kind.hpp"
#include "ui/panel_model.hpp"
#include "ui/view_caption.hpp"
#include "workflow/transition_table.hpp"

#include <algorithm>
#include <gtest/gtest.h>
#include <set>

namespace steerseg::test {

using model::Action;
using model::State;

namespace {

// The variant index of each action type, by name for the messages.
template <typename T> std::size_t indexOf() {
    return Action(T{}).index();
}

std::set<std::size_t> kinds(const std::vector<Action>& actions) {
    std::set<std::size_t> out;
    for (const Action& a : actions) {
        out.insert(a.index());
    }
    return out;
}

workflow::Status status(State state) {
    workflow::Status st;
    st.state = state;
    st.scan.name = "sample";
    st.scan.units = "HU";
    st.scan.dims = {64, 64, 64};
    st.scan.minValue = -1000.0;
    st.scan.maxValue = 2000.0;
    st.presets = {"CT soft tissue", "CT bone"};
    st.canUndo = true;
    st.canRedo = true;
    st.hasLevelSet = true;
    st.seeds = 2;
    return st;
}

const std::vector<std::string> kScans{"builtin:sample", "/data/ct/CT_sarcoma.nii.gz",
                                      "/data/dicom/head/"};

// The panel of a status as the workflow publishes it: with what its table allows now.
ui::PanelModel modelOf(workflow::Status st) {
    st.allowed = workflow::allowedActions(st.state, workflow::factsOf(st));
    return ui::buildPanelModel(st, kScans);
}

} // namespace

// For each state, every action the workflow offers there can be reached by touching the
// panel (taps on the views add Probe, AddSeed, Erase, PageSlice, RotateView and ZoomView:
// ui_interaction_test).
TEST(UiPanelModel, TheStructuresListSelectsHidesDeletesAndAddsTheSiteOnes) {
    workflow::Status st = status(State::Paused);
    model::StructureInfo liver;
    liver.name = "Liver";
    model::StructureInfo spleen;
    spleen.name = "Spleen";
    spleen.visible = false;
    st.structures = {{liver, 1530.25, true, false}, {spleen, 0.0, false, true}};
    st.structureKinds = {"Liver", "Spleen", "Left kidney"};
    const ui::PanelModel m = modelOf(st);
    ASSERT_EQ(m.structures.size(), 6U);
    EXPECT_EQ(m.structures[0].label, "Liver  1530.2 ml##structure0");
    EXPECT_TRUE(m.structures[0].active);
    EXPECT_FALSE(m.structures[0].enabled) << "the active one is selected already";
    EXPECT_EQ(m.structures[3].label, "Spleen  (empty)##structure1");
    EXPECT_TRUE(m.structures[3].enabled);
    EXPECT_EQ(m.structures[4].label, "Show##structure1");
    const auto* show = std::get_if<model::EditStructure>(&m.structures[4].action);
    ASSERT_NE(show, nullptr);
    EXPECT_EQ(show->op, model::StructureOp::Show);
    EXPECT_EQ(show->name, "Spleen");
    // The site's structures not in the session yet, then a free one.
    ASSERT_EQ(m.newStructures.size(), 2U);
    EXPECT_EQ(m.newStructures[0].label, "+ Left kidney##new");
    EXPECT_EQ(m.newStructures[1].label, "+ Structure 3##new");
    // Review's table, one row a measured structure.
    workflow::Status review = status(State::Review);
    MaskMeasurements f;
    f.volumeMl = 1530.25;
    f.axial.longest.lengthMm = 112.44;
    f.axial.perpendicular.lengthMm = 80.06;
    f.longest3d.lengthMm = 140.3;
    f.intensity.mean = 54.2;
    f.intensity.sd = 12.4;
    review.measurements = {{0, "Liver", {1.0, 0.5, 0.4}, true, f}};
    const ui::PanelModel rm = modelOf(review);
    ASSERT_EQ(rm.measurements.size(), 1U);
    EXPECT_EQ(rm.measurements[0].volume, "1530.2 ml");
    EXPECT_EQ(rm.measurements[0].axes, "112.4 x 80.1 mm");
    EXPECT_EQ(rm.measurements[0].longest, "140.3 mm");
    EXPECT_EQ(rm.measurements[0].values, "54 +- 12 HU");
    // A lone structure cannot be deleted.
    st.structures.pop_back();
    EXPECT_FALSE(modelOf(st).structures[2].enabled);
}

TEST(UiPanelModel, EveryMeaningfulActionIsReachableByTouch) {
    const std::size_t load = indexOf<model::LoadScan>();
    const std::size_t preset = indexOf<model::ApplyPreset>();
    const std::size_t set = indexOf<model::SetParam>();
    const std::size_t nudge = indexOf<model::NudgeParam>();
    const std::size_t select = indexOf<model::SelectParam>();
    const std::size_t window = indexOf<model::SetWindow>();
    const std::size_t eraseMode = indexOf<model::SetEraseMode>();
    const std::size_t run = indexOf<model::Run>();
    const std::size_t pause = indexOf<model::Pause>();
    const std::size_t exportMask = indexOf<model::Export>();
    const std::size_t undo = indexOf<model::Undo>();
    const std::size_t redo = indexOf<model::Redo>();
    const std::size_t restart = indexOf<model::Restart>();
    const std::size_t proceed = indexOf<model::Proceed>();
    const std::size_t back = indexOf<model::Back>();
    const std::size_t dismiss = indexOf<model::Dismiss>();
    const std::size_t show = indexOf<model::ShowSlices>();
    const std::size_t speed = indexOf<model::SetSpeed>();
    const std::size_t boxMode = indexOf<model::SetBoxMode>();
    const std::size_t structure = indexOf<model::EditStructure>();
    const std::set<std::size_t> steering{preset, set,     nudge, select, eraseMode, undo,
                                         redo,   restart, show,  speed,  boxMode};
    const auto with = [](std::set<std::size_t> s, std::initializer_list<std::size_t> more) {
        s.insert(more);
        return s;
    };
    const std::vector<std::pair<State, std::set<std::size_t>>> expected{
        {State::NoScan, {load}},
        {State::Loading, {}},
        {State::Inspect,
         {load, preset, set, nudge, select, window, undo, redo, show, proceed, speed, boxMode,
          structure}},
        {State::Seeding, with(steering, {run, back, structure})},
        // Structures wait for a pause: no list while the front moves.
        {State::Evolving, with(steering, {pause, proceed})},
        {State::Paused, with(steering, {run, proceed, structure})},
        {State::Review, {show, back, proceed, structure}},
        {State::Exporting, {}},
        {State::Done, {load, exportMask, back, show, structure}},
        {State::Error, {dismiss}},
    };
    for (const auto& [state, want] : expected) {
        const ui::PanelModel m = modelOf(status(state));
        const std::set<std::size_t> got = kinds(ui::reachableActions(m));
        for (std::size_t k : want) {
            EXPECT_TRUE(got.count(k)) << ui::stateLabel(state) << " lacks action #" << k;
        }
        // Nothing is offered where it means nothing (a panel that offered everything
        // everywhere would pass the check above).
        for (std::size_t k : got) {
            EXPECT_TRUE(want.count(k)) << ui::stateLabel(state) << " offers action #" << k;
        }
    }
}

// Issue 25, item 1: a lost audit log stays above whatever message the state shows, and the panel
// offers the acknowledgement export waits for.
TEST(UiPanelModel, ALostAuditLogStaysAboveTheMessageAndOffersTheAcknowledgement) {
    workflow::Status st = status(State::Review);
    st.message = "exported to /x/out.nii.gz";
    st.auditProblem = "audit log /var/lib/steerseg/audit.jsonl: the disk is full";
    ui::PanelModel m = modelOf(st);
    EXPECT_NE(m.auditAlarm.find("the disk is full"), std::string::npos) << m.auditAlarm;
    EXPECT_EQ(m.message, st.message);
    const std::set<std::size_t> got = kinds(ui::reachableActions(m));
    EXPECT_TRUE(got.count(indexOf<model::AcknowledgeAudit>()));
    st.auditAcknowledged = true;
    m = modelOf(st);
    EXPECT_NE(m.auditAlarm.find("Acknowledged"), std::string::npos) << m.auditAlarm;
    EXPECT_FALSE(kinds(ui::reachableActions(m)).count(indexOf<model::AcknowledgeAudit>()));
    st.auditProblem.clear();
    EXPECT_TRUE(modelOf(st).auditAlarm.empty());
}

TEST(UiPanelModel, ProceedIsLabelledForTheState) {
    EXPECT_EQ(ui::proceedLabel(State::Inspect), "Seed");
    EXPECT_EQ(ui::proceedLabel(State::Seeding), "Run");
    EXPECT_EQ(ui::proceedLabel(State::Evolving), "Review");
    EXPECT_EQ(ui::proceedLabel(State::Paused), "Review");
    EXPECT_EQ(ui::proceedLabel(State::Review), "Export");
    EXPECT_EQ(ui::proceedLabel(State::NoScan), "");
    const ui::PanelModel seeding = modelOf(status(State::Seeding));
    const auto run = std::find_if(seeding.nav.begin(), seeding.nav.end(),
                                  [](const ui::PanelButton& b) { return b.label == "Run"; });
    ASSERT_NE(run, seeding.nav.end());
    EXPECT_TRUE(std::holds_alternative<model::Run>(run->action));
    const ui::PanelModel review = modelOf(status(State::Review));
    EXPECT_EQ(review.nav.back().label, "Export##proceed");
}

TEST(UiPanelModel, ParametersReadoutsAndToggles) {
    workflow::Status st = status(State::Paused);
    st.selected = model::Param::Eps;
    st.params.T = 40.0F;
    st.params.eps = 25.0F;
    st.params.alpha = 0.9F;
    st.radius = 4.0;
    st.iterations = 272;
    st.volumeMl = 7.126;
    st.converged = true;
    st.eraseMode = true;
    st.ranges[static_cast<std::size_t>(model::Param::T)] = {-200.0, 300.0, 1.0};
    const ui::PanelModel m = modelOf(st);
    ASSERT_EQ(m.params.size(), 4U);
    EXPECT_EQ(m.params[0].range.min, -200.0);
    EXPECT_EQ(m.params[0].value, 40.0);
    EXPECT_LT(m.params[1].range.min, m.params[1].range.max) << "a range even where none was given";
    EXPECT_FALSE(m.params[0].selected);
    EXPECT_TRUE(m.params[1].selected);
    EXPECT_EQ(m.params[3].label, "brush");
    EXPECT_EQ(m.params[3].value, 4.0);
    const auto readout = [&](const std::string& label) {
        for (const ui::Readout& r : m.readouts) {
            if (r.label == label) {
                return r.value;
            }
        }
        return std::string("(none)");
    };
    EXPECT_EQ(readout("T"), "40.0 HU");
    EXPECT_EQ(readout("alpha"), "0.90");
    EXPECT_EQ(readout("iter"), "272");
    EXPECT_EQ(readout("ml"), "7.13");
    EXPECT_EQ(readout("done"), "yes");
    EXPECT_EQ(m.banner, "Paused");
    EXPECT_EQ(m.scanName, "sample");
    const auto erase = std::find_if(m.tools.begin(), m.tools.end(), [](const ui::PanelButton& b) {
        return std::holds_alternative<model::SetEraseMode>(b.action);
    });
    ASSERT_NE(erase, m.tools.end());
    EXPECT_TRUE(erase->active);
    EXPECT_FALSE(std::get<model::SetEraseMode>(erase->action).erase) << "a tap turns it off";
}

TEST(UiPanelModel, TheSpeedsAreOfferedWhereParametersAre) {
    for (State state : {State::Inspect, State::Seeding, State::Evolving, State::Paused}) {
        workflow::Status st = status(state);
        st.speed = model::SpeedKind::Edge;
        st.speedInForce = model::SpeedKind::Edge;
        const ui::PanelModel m = modelOf(st);
        ASSERT_EQ(m.speeds.size(), 3U) << ui::stateLabel(state);
        const std::vector<std::string> labels{"Threshold##speed", "Edge##speed", "Classify##speed"};
        for (std::size_t i = 0; i < 3; ++i) {
            EXPECT_EQ(m.speeds[i].label, labels[i]);
            EXPECT_EQ(std::get<model::SetSpeed>(m.speeds[i].action).kind, model::kSpeedKinds[i]);
            EXPECT_EQ(m.speeds[i].active, i == 1) << "the chosen speed is highlighted";
            EXPECT_TRUE(m.speeds[i].enabled);
        }
        EXPECT_TRUE(m.exampleTools.empty()) << "examples are classify's";
        EXPECT_TRUE(m.examples.empty());
        EXPECT_TRUE(m.speedNote.empty());
    }
    for (State state : {State::NoScan, State::Loading, State::Review, State::Exporting, State::Done,
                        State::Error}) {
        EXPECT_TRUE(modelOf(status(state)).speeds.empty()) << ui::stateLabel(state);
    }
}

// A speed this GPU computed wrong at start-up (issue 47) is not offered, and the alarm that says
// why stands in every state.
TEST(UiPanelModel, ASpeedOffOnThisGpuIsLeftOutAndTheAlarmStands) {
    for (State state : {State::NoScan, State::Inspect, State::Evolving, State::Done}) {
        workflow::Status st = status(state);
        st.speedsOff = {model::SpeedKind::Classify};
        st.gpuAlarm = "GPU CHECK FAILED. The classify speed is off.";
        const ui::PanelModel m = modelOf(st);
        EXPECT_EQ(m.gpuAlarm, st.gpuAlarm) << ui::stateLabel(state);
        for (const auto& speed : m.speeds) {
            EXPECT_NE(std::get<model::SetSpeed>(speed.action).kind, model::SpeedKind::Classify);
        }
        if (state == State::Inspect || state == State::Evolving) {
            EXPECT_EQ(m.speeds.size(), 2U) << ui::stateLabel(state);
        }
    }
    EXPECT_TRUE(modelOf(status(State::Inspect)).gpuAlarm.empty());
}

const ui::PanelButton* buttonLabelled(const ui::PanelModel& m, const std::string& label) {
    for (const ui::PanelButton& b : m.tools) {
        if (b.label == label) {
            return &b;
        }
    }
    return nullptr;
}

// The box (docs/ui.md): a toggle where the table lets a box be set, and Clear box once there
// is one, enabled as the table allows it.
TEST(UiPanelModel, TheBoxToggleAndClearBoxFollowTheTable) {
    workflow::Status st = status(State::Inspect);
    st.hasLevelSet = false;
    ui::PanelModel m = modelOf(st);
    const ui::PanelButton* toggle = buttonLabelled(m, "Box: off");
    ASSERT_NE(toggle, nullptr);
    EXPECT_FALSE(toggle->active);
    EXPECT_TRUE(std::get<model::SetBoxMode>(toggle->action).on);
    EXPECT_EQ(buttonLabelled(m, "Clear box"), nullptr) << "no box to clear";

    st = status(State::Paused);
    st.boxMode = true;
    st.box = model::Box{{2, 3, 4}, {20, 30, 40}};
    m = modelOf(st);
    toggle = buttonLabelled(m, "Box: on");
    ASSERT_NE(toggle, nullptr);
    EXPECT_TRUE(toggle->active);
    EXPECT_FALSE(std::get<model::SetBoxMode>(toggle->action).on);
    EXPECT_NE(m.hint.find("Drag on a slice to draw the box"), std::string::npos) << m.hint;
    const ui::PanelButton* clear = buttonLabelled(m, "Clear box");
    ASSERT_NE(clear, nullptr);
    EXPECT_TRUE(clear->enabled);
    EXPECT_TRUE(std::holds_alternative<model::ClearBox>(clear->action));
    EXPECT_TRUE(kinds(ui::reachableActions(m)).count(indexOf<model::ClearBox>()));

    // Where the table refuses a box (review), neither is there.
    st.state = State::Review;
    m = modelOf(st);
    EXPECT_EQ(buttonLabelled(m, "Box: on"), nullptr);
    EXPECT_EQ(buttonLabelled(m, "Clear box"), nullptr);
    EXPECT_FALSE(kinds(ui::reachableActions(m)).count(indexOf<model::ClearBox>()));
}

TEST(UiPanelModel, ClassifyShowsItsExamplesAndTools) {
    workflow::Status st = status(State::Paused);
    st.speed = model::SpeedKind::Classify;
    st.speedInForce = model::SpeedKind::Threshold;
    st.insideExamples.resize(2);
    ui::PanelModel m = modelOf(st);
    EXPECT_TRUE(m.speeds[2].active);
    EXPECT_EQ(m.examples, "2 inside, 0 outside");
    EXPECT_EQ(m.speedNote, "Classify needs an outside example; threshold runs until then.");
    ASSERT_EQ(m.exampleTools.size(), 2U);
    EXPECT_EQ(m.exampleTools[0].label, "Outside: off");
    EXPECT_TRUE(std::get<model::SetOutsideMode>(m.exampleTools[0].action).outside);
    EXPECT_FALSE(m.exampleTools[0].active);
    EXPECT_TRUE(std::holds_alternative<model::ClearExamples>(m.exampleTools[1].action));
    EXPECT_TRUE(m.exampleTools[1].enabled);
    const std::set<std::size_t> got = kinds(ui::reachableActions(m));
    EXPECT_TRUE(got.count(indexOf<model::SetOutsideMode>()));
    EXPECT_TRUE(got.count(indexOf<model::ClearExamples>()));

    st.insideExamples.clear();
    st.outsideMode = true;
    m = modelOf(st);
    EXPECT_EQ(m.exampleTools[0].label, "Outside: on");
    EXPECT_TRUE(m.exampleTools[0].active);
    EXPECT_FALSE(std::get<model::SetOutsideMode>(m.exampleTools[0].action).outside);
    EXPECT_FALSE(m.exampleTools[1].enabled) << "nothing to clear";
    EXPECT_FALSE(kinds(ui::reachableActions(m)).count(indexOf<model::ClearExamples>()));
    EXPECT_EQ(m.speedNote, "Classify needs an inside example (a probe or a seed) and an outside "
                           "example; threshold runs until then.");

    st.insideExamples.resize(1);
    st.outsideExamples.resize(3);
    st.speedInForce = model::SpeedKind::Classify;
    m = modelOf(st);
    EXPECT_EQ(m.examples, "1 inside, 3 outside");
    EXPECT_TRUE(m.speedNote.empty()) << "the classifier runs";

    // A painted stroke's spheres are examples too: only the outside one is missing.
    st.insideExamples.clear();
    st.outsideExamples.clear();
    st.paintedInside.resize(40);
    st.speedInForce = model::SpeedKind::Threshold;
    m = modelOf(st);
    EXPECT_EQ(m.examples, "0 inside, 0 outside; painted or corrected 40 inside, 0 outside spheres");
    EXPECT_EQ(m.speedNote, "Classify needs an outside example; threshold runs until then.");
}

TEST(UiPanelModel, UndoGreyedWithNothingToUndo) {
    workflow::Status st = status(State::Seeding);
    st.canUndo = false;
    const ui::PanelModel m = modelOf(st);
    const std::set<std::size_t> got = kinds(ui::reachableActions(m));
    EXPECT_FALSE(got.count(indexOf<model::Undo>()));
    EXPECT_TRUE(got.count(indexOf<model::Redo>()));
}

TEST(UiPanelModel, ButtonsWorkAsTheWorkflowAllows) {
    workflow::Status st = status(State::Paused);
    st.speed = model::SpeedKind::Classify;
    st.insideExamples.resize(1);
    // What the workflow published, not what the panel could derive from the counts.
    st.allowed = model::ActionKinds{model::ActionKind::Redo};
    const ui::PanelModel m = ui::buildPanelModel(st, kScans);
    const auto enabled = [&](const std::vector<ui::PanelButton>& list, const std::string& label) {
        const auto b = std::find_if(list.begin(), list.end(),
                                    [&](const ui::PanelButton& x) { return x.label == label; });
        EXPECT_NE(b, list.end()) << label;
        return b != list.end() && b->enabled;
    };
    EXPECT_FALSE(enabled(m.tools, "Undo"));
    EXPECT_TRUE(enabled(m.tools, "Redo"));
    EXPECT_FALSE(enabled(m.tools, "Restart"));
    EXPECT_FALSE(enabled(m.exampleTools, "Clear examples"));
}

TEST(UiPanelModel, ControllersAreListedConnectedOrNot) {
    workflow::Status st = status(State::Paused);
    EXPECT_TRUE(modelOf(st).devices.empty());
    st.devices = {{"shuttle", "shuttle", true}, {"pedal", "gpio_input", false}};
    const ui::PanelModel m = modelOf(st);
    ASSERT_EQ(m.devices.size(), 2U);
    EXPECT_EQ(m.devices[0].label, "shuttle");
    EXPECT_EQ(m.devices[0].value, "connected");
    EXPECT_EQ(m.devices[1].label, "pedal");
    EXPECT_EQ(m.devices[1].value, "disconnected");
}

// The DICOM node's series (Status::received, filled by the kiosk): a complete one is a LoadScan
// of its folder, one still arriving is greyed out; the note and the outbox's lines are shown.
TEST(UiPanelModel, ReceivedSeriesAreLoadButtonsAndTheOutboxIsShown) {
    workflow::Status st = status(State::NoScan);
    EXPECT_TRUE(modelOf(st).received.empty());
    st.received = {{"/store/1.2/1.2.3", "MR 2001-03-16, FSE PD (20 images) - arriving", true},
                   {"/store/1.2/1.2.4", "CT PAT1 (60 images)", false}};
    st.receivedNote = "New series: CT PAT1 (60 images)";
    st.outbox = {"seg.dcm to pacs: waiting, attempt 1 failed (connection refused); next in 5 s"};
    const ui::PanelModel m = modelOf(st);
    ASSERT_EQ(m.received.size(), 2U);
    EXPECT_FALSE(m.received[0].enabled);
    EXPECT_TRUE(m.received[1].enabled);
    EXPECT_EQ(m.received[1].label, "CT PAT1 (60 images)##received1");
    EXPECT_EQ(std::get<model::LoadScan>(m.received[1].action).path, "/store/1.2/1.2.4");
    EXPECT_EQ(m.receivedNote, st.receivedNote);
    EXPECT_EQ(m.outbox, st.outbox);
    const auto reachable = ui::reachableActions(m);
    const auto loads = std::count_if(reachable.begin(), reachable.end(), [](const Action& a) {
        const auto* load = std::get_if<model::LoadScan>(&a);
        return load != nullptr && load->path.starts_with("/store/");
    });
    EXPECT_EQ(loads, 1) << "the arriving series is not loadable yet";
    // While segmenting the list is not offered; the outbox still shows what waits.
    st.state = State::Evolving;
    EXPECT_TRUE(modelOf(st).received.empty());
    EXPECT_EQ(modelOf(st).outbox.size(), 1U);
}

TEST(UiPanelModel, ScansAndViews) {
    const ui::PanelModel m = modelOf(status(State::NoScan));
    ASSERT_EQ(m.scans.size(), 3U);
    EXPECT_EQ(m.scans[0].label, "Load Sample##scan0");
    EXPECT_EQ(std::get<model::LoadScan>(m.scans[1].action).path, kScans[1]);
    EXPECT_EQ(ui::scanLabel("/data/ct/CT_sarcoma.nii.gz"), "CT_sarcoma.nii.gz");
    EXPECT_EQ(ui::scanLabel("/data/dicom/head/"), "head");
    EXPECT_EQ(ui::scanLabel(""), "");

    workflow::Status st = status(State::Inspect);
    st.view.first = model::SliceAxis::Axial;
    st.view.second = model::SliceAxis::Coronal;
    const ui::PanelModel inspect = modelOf(st);
    ASSERT_EQ(inspect.views.size(), 6U);
    EXPECT_TRUE(inspect.views[0].active);
    const auto sagittalFirst = std::get<model::ShowSlices>(inspect.views[2].action);
    EXPECT_EQ(sagittalFirst.first, model::SliceAxis::Sagittal);
    EXPECT_EQ(sagittalFirst.second, model::SliceAxis::Coronal);
    EXPECT_TRUE(inspect.views[4].active);
    ASSERT_TRUE(inspect.window);
    EXPECT_EQ(inspect.window->width, 3000.0) << "unset window: the whole range";

    workflow::Status loading = status(State::Loading);
    loading.loadProgress = 0.4;
    const ui::PanelModel lm = modelOf(loading);
    ASSERT_TRUE(lm.progress);
    EXPECT_EQ(*lm.progress, 0.4);

    workflow::Status error = status(State::Error);
    error.message = "CT.nii: not a NIfTI file";
    const ui::PanelModel em = modelOf(error);
    EXPECT_TRUE(em.error);
    EXPECT_EQ(em.message, error.message);
}

TEST(UiViewCaption, NamesTheViewAndTheSlice) {
    render::SliceFrame f;
    f.sliceAxis = 2;
    f.slice = 40;
    EXPECT_EQ(ui::view3dCaption(), "3D");
    EXPECT_EQ(ui::contourCaption(model::SliceAxis::Axial, f, {64, 64, 80}), "Axial  slice 41/80");
    f.sliceAxis = 1;
    f.slice = 11;
    EXPECT_EQ(ui::speedCaption(model::SliceAxis::Coronal, f, {64, 80, 80}),
              "Coronal \u2014 speed  12/80");
}

// The export step names what Export will write, as the config enables it.
TEST(UiPanelModel, ExportStepNamesTheFormats) {
    workflow::Status st = status(State::Review);
    st.exportFormats = {"nii.gz", "seg.nrrd", "stl"};
    const ui::PanelModel review = modelOf(st);
    EXPECT_NE(review.hint.find("Export writes .nii.gz, .seg.nrrd, .stl."), std::string::npos)
        << review.hint;
    st.state = State::Done;
    EXPECT_NE(modelOf(st).hint.find(".seg.nrrd"), std::string::npos);
    st.state = State::Seeding;
    EXPECT_EQ(modelOf(st).hint.find("Export writes"), std::string::npos);
}

} // namespace steerseg::test
