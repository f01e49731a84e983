// Renaming and recolouring the active structure from the panel (ui/structure_editing and the
// panel model's Rename, Colour and swatches), against the real workflow on the in-memory
// engine: the panel completes the action, the workflow decides, the panel follows its status.
#include "model/structure.hpp"
#include "support/workflow_rig.hpp"
#include "ui/panel_model.hpp"
#include "ui/structure_editing.hpp"
#include "workflow/transition_table.hpp"

#include <algorithm>
#include <gtest/gtest.h>
#include <string_view>

namespace steerseg::test {

namespace {

using model::State;
using model::StructureOp;
using ui::Key;
using ui::KeyKind;

Key key(KeyKind kind) {
    return {kind, 0, 1.0};
}

ui::PanelModel panelOf(workflow::Status st, const ui::PanelEditors& editors = {}) {
    st.allowed = workflow::allowedActions(st.state, workflow::factsOf(st));
    return ui::buildPanelModel(st, {}, editors);
}

ui::PanelModel panelOf(const Rig& rig, const ui::StructureEditing& editing) {
    return ui::buildPanelModel(rig.status(), {}, {editing.renameOpen(), editing.coloursOpen()});
}

const ui::PanelButton* button(const std::vector<ui::PanelButton>& list, std::string_view label) {
    const auto it = std::find_if(list.begin(), list.end(),
                                 [&](const ui::PanelButton& b) { return b.label == label; });
    return it == list.end() ? nullptr : &*it;
}

// What the panel does on a tap on Rename or Colour: opens the editor for the name it carries.
void tapTool(ui::StructureEditing& editing, const ui::PanelModel& m, std::string_view label) {
    const ui::PanelButton* b = button(m.structureTools, label);
    ASSERT_NE(b, nullptr) << label;
    ASSERT_TRUE(b->enabled) << label;
    const std::string& name = std::get<model::EditStructure>(b->action).name;
    if (b->completion == ui::Completion::Name) {
        editing.openRename(name);
    } else {
        editing.toggleColours(name);
    }
}

// Clears the keyboard's text and types `text` (a capital after '^'), then OK.
std::optional<model::Action> retype(ui::StructureEditing& editing, std::string_view text) {
    editing.press(key(KeyKind::Clear));
    bool shift = false;
    for (char c : text) {
        if (c == '^') {
            shift = true;
            continue;
        }
        if (shift) {
            editing.press(key(KeyKind::Shift));
            shift = false;
        }
        EXPECT_FALSE(editing.press(c == ' ' ? key(KeyKind::Space) : Key{KeyKind::Character, c, 1}));
    }
    return editing.press(key(KeyKind::Ok));
}

const workflow::StructureRow& row(const Rig& rig, std::size_t i) {
    return rig.status().structures.at(i);
}

} // namespace

TEST(UiStructureEditing, RenameAndColourAreOfferedForTheActiveStructureWhereEditsAreAllowed) {
    workflow::Status st;
    st.scan.dims = {16, 16, 16};
    st.hasLevelSet = true;
    st.seeds = 1;
    model::StructureInfo liver;
    liver.name = "Liver";
    liver.colour = model::paletteColour(3);
    model::StructureInfo spleen;
    spleen.name = "Spleen";
    st.structures = {{spleen, 0.0, false, true}, {liver, 12.0, true, false}};
    for (State s : {State::NoScan, State::Loading, State::Inspect, State::Seeding, State::Evolving,
                    State::Paused, State::Review, State::Exporting, State::Done, State::Error}) {
        st.state = s;
        const ui::PanelModel m = panelOf(st);
        const bool editable = workflow::allowedActions(s, workflow::factsOf(st))
                                  .contains(model::ActionKind::EditStructure);
        SCOPED_TRACE(ui::stateLabel(s));
        if (!editable) {
            EXPECT_TRUE(m.structureTools.empty());
            continue;
        }
        ASSERT_EQ(m.structureTools.size(), 2U);
        const ui::PanelButton* rename = button(m.structureTools, "Rename##structure");
        ASSERT_NE(rename, nullptr);
        EXPECT_EQ(rename->completion, ui::Completion::Name);
        const auto& renameAction = std::get<model::EditStructure>(rename->action);
        EXPECT_EQ(renameAction.op, StructureOp::Rename);
        EXPECT_EQ(renameAction.name, "Liver") << "the active one, not the first";
        const ui::PanelButton* colour = button(m.structureTools, "Colour##structure");
        ASSERT_NE(colour, nullptr);
        EXPECT_EQ(colour->completion, ui::Completion::Colour);
        EXPECT_EQ(colour->swatch, std::optional(liver.colour)) << "drawn in its colour";
        EXPECT_TRUE(m.colours.empty()) << "the swatches wait for a tap on Colour";
        // Neither sends anything by itself: the keyboard and the swatches complete them.
        for (const model::Action& a : ui::reachableActions(m)) {
            if (const auto* e = std::get_if<model::EditStructure>(&a)) {
                EXPECT_NE(e->op, StructureOp::Rename);
                EXPECT_NE(e->op, StructureOp::Recolour);
            }
        }
    }
    EXPECT_TRUE(workflow::allowedActions(State::Paused, workflow::factsOf(st))
                    .contains(model::ActionKind::EditStructure))
        << "the loop above checked some state with the tools";
}

TEST(UiStructureEditing, TheSwatchesAreThePalettesAndEachRecoloursTheActiveStructure) {
    workflow::Status st;
    st.state = State::Paused;
    st.hasLevelSet = true;
    model::StructureInfo liver;
    liver.name = "Liver";
    liver.colour = model::paletteColour(2);
    st.structures = {{liver, 12.0, true, false}};
    const ui::PanelModel m = panelOf(st, {.rename = false, .colours = true});
    ASSERT_EQ(m.colours.size(), 8U) << "the palette's cycle";
    for (std::size_t i = 0; i < m.colours.size(); ++i) {
        const ui::PanelButton& b = m.colours[i];
        EXPECT_EQ(b.swatch, std::optional(model::paletteColour(i)));
        EXPECT_EQ(b.active, i == 2) << "the structure's own colour is marked";
        const auto& e = std::get<model::EditStructure>(b.action);
        EXPECT_EQ(e.op, StructureOp::Recolour);
        EXPECT_EQ(e.name, "Liver");
        EXPECT_EQ(e.colour, model::paletteColour(i));
    }
    const std::vector<model::Action> reachable = ui::reachableActions(m);
    EXPECT_EQ(std::count_if(reachable.begin(), reachable.end(),
                            [](const model::Action& a) {
                                const auto* e = std::get_if<model::EditStructure>(&a);
                                return e != nullptr && e->op == StructureOp::Recolour;
                            }),
              8);
    const ui::PanelButton* colour = button(m.structureTools, "Colour##structure");
    ASSERT_NE(colour, nullptr);
    EXPECT_TRUE(colour->active) << "Colour shows that its swatches are open";
}

TEST(UiStructureEditing, TheKeyboardRenamesTheActiveStructureUndoably) {
    Rig rig;
    rig.load();
    ui::StructureEditing editing;
    editing.follow(rig.status());
    tapTool(editing, panelOf(rig, editing), "Rename##structure");
    ASSERT_TRUE(editing.renameOpen());
    ASSERT_NE(editing.keyboard(), nullptr);
    EXPECT_EQ(editing.keyboard()->text(), model::kFirstStructureName) << "opens on the name";
    EXPECT_TRUE(button(panelOf(rig, editing).structureTools, "Rename##structure")->active);

    const std::optional<model::Action> rename = retype(editing, "^left kidney");
    ASSERT_TRUE(rename);
    const auto& e = std::get<model::EditStructure>(*rename);
    EXPECT_EQ(e.op, StructureOp::Rename);
    EXPECT_EQ(e.name, model::kFirstStructureName);
    EXPECT_EQ(e.to, "Left kidney");
    EXPECT_TRUE(editing.renameOpen()) << "open until the workflow's status says how it went";

    ASSERT_TRUE(rig.act(*rename).accepted);
    editing.follow(rig.status());
    EXPECT_FALSE(editing.renameOpen()) << "taken: the keyboard closes";
    EXPECT_EQ(row(rig, 0).info.name, "Left kidney");

    ASSERT_TRUE(rig.act(model::Undo{}).accepted);
    EXPECT_EQ(row(rig, 0).info.name, model::kFirstStructureName) << "one undo step";
}

TEST(UiStructureEditing, ANameTheWorkflowRefusesKeepsTheKeyboardOpenWithItsReason) {
    Rig rig;
    rig.load();
    ASSERT_TRUE(rig.act(model::EditStructure{StructureOp::Add, "Spleen", {}, {}}).accepted);
    ui::StructureEditing editing;
    editing.follow(rig.status());
    tapTool(editing, panelOf(rig, editing), "Rename##structure");
    ASSERT_EQ(editing.renaming(), "Spleen");

    // A duplicate.
    std::optional<model::Action> rename = retype(editing, "^segment 1");
    ASSERT_TRUE(rename);
    const workflow::Workflow::Outcome refused = rig.act(*rename);
    ASSERT_FALSE(refused.accepted);
    editing.follow(rig.status());
    EXPECT_TRUE(editing.renameOpen());
    EXPECT_EQ(editing.problem(), refused.reason);
    EXPECT_NE(editing.problem().find("exists already"), std::string::npos) << editing.problem();
    EXPECT_EQ(editing.keyboard()->text(), "Segment 1") << "the text stays, to be corrected";

    // A name structureNameProblem refuses: a trailing space.
    rename = retype(editing, "^spleen ");
    ASSERT_TRUE(rename);
    ASSERT_FALSE(rig.act(*rename).accepted);
    editing.follow(rig.status());
    EXPECT_TRUE(editing.renameOpen());
    EXPECT_EQ(editing.problem(), model::structureNameProblem("Spleen "));
    EXPECT_EQ(row(rig, 1).info.name, "Spleen");

    // The name as it was: nothing to send, the keyboard closes.
    editing.press(key(KeyKind::Backspace));
    EXPECT_FALSE(editing.press(key(KeyKind::Ok)));
    EXPECT_FALSE(editing.renameOpen());

    // Cancel gives nothing and closes.
    editing.openRename("Spleen");
    editing.press(key(KeyKind::Clear));
    EXPECT_FALSE(editing.press(key(KeyKind::Cancel)));
    EXPECT_FALSE(editing.renameOpen());
    EXPECT_EQ(row(rig, 1).info.name, "Spleen");
}

TEST(UiStructureEditing, ASwatchRecoloursUndoably) {
    Rig rig;
    rig.load();
    ui::StructureEditing editing;
    tapTool(editing, panelOf(rig, editing), "Colour##structure");
    ASSERT_TRUE(editing.coloursOpen());
    const ui::PanelModel m = panelOf(rig, editing);
    ASSERT_GT(m.colours.size(), 4U);
    const glm::dvec3 before = row(rig, 0).info.colour;
    ASSERT_NE(before, model::paletteColour(4));
    ASSERT_TRUE(rig.act(m.colours[4].action).accepted);
    EXPECT_EQ(row(rig, 0).info.colour, model::paletteColour(4));
    ASSERT_TRUE(rig.act(model::Undo{}).accepted);
    EXPECT_EQ(row(rig, 0).info.colour, before);
    // Colour again closes the swatches.
    tapTool(editing, panelOf(rig, editing), "Colour##structure");
    EXPECT_FALSE(editing.coloursOpen());
}

TEST(UiStructureEditing, TheEditorsCloseWhenTheirStructureCannotBeEditedNow) {
    Rig rig;
    rig.load();
    rig.seed();
    ui::StructureEditing editing;
    editing.openRename(std::string(model::kFirstStructureName));
    editing.follow(rig.status());
    EXPECT_TRUE(editing.renameOpen());
    ASSERT_TRUE(rig.act(model::Run{}).accepted);
    ASSERT_EQ(rig.state(), State::Evolving);
    editing.follow(rig.status());
    EXPECT_FALSE(editing.renameOpen()) << "structures wait for a pause";
    EXPECT_TRUE(panelOf(rig, editing).structureTools.empty());

    ASSERT_TRUE(rig.act(model::Pause{}).accepted);
    editing.toggleColours(std::string(model::kFirstStructureName));
    editing.follow(rig.status());
    EXPECT_TRUE(editing.coloursOpen());
    ASSERT_TRUE(rig.act(model::EditStructure{StructureOp::Add, "Spleen", {}, {}}).accepted);
    editing.follow(rig.status());
    EXPECT_FALSE(editing.coloursOpen()) << "another structure is active";

    editing.openRename("Spleen");
    ASSERT_TRUE(rig.act(model::EditStructure{
                            StructureOp::Select, std::string(model::kFirstStructureName), {}, {}})
                    .accepted);
    editing.follow(rig.status());
    EXPECT_FALSE(editing.renameOpen()) << "selected away";
}

} // namespace steerseg::test
