// The session's structures (model::EditStructure, docs/structures.md) on the in-memory engine:
// what the engine holds as each one is left and taken up again, what it may not grow into,
// undo and redo across structures, what an export is given, and what is refused.
#include "support/workflow_rig.hpp"
#include "workflow/audit_log.hpp"

#include <filesystem>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

namespace steerseg::test {
namespace {

using model::State;
using model::StructureOp;

model::EditStructure op(StructureOp o, std::string name, std::string to = {}) {
    return {o, std::move(name), std::move(to), glm::dvec3(0.0)};
}

// A rig with a first structure seeded at the fake's centre and a second added (active, empty).
struct TwoStructures : Rig {
    explicit TwoStructures(workflow::Settings s = testSettings()) : Rig(std::move(s)) {
        load();
        seed({8.0, 6.0, 4.0}, 2.0);
        firstVoxels = engine.insideVoxels();
        firstMask = engine.levelSetMask();
        EXPECT_TRUE(act(op(StructureOp::Add, "Spleen")).accepted);
    }
    std::size_t firstVoxels = 0;
    MaskRuns firstMask;
};

TEST(WorkflowStructures, AddingKeepsTheActiveOneAsAMaskAndStartsAnEmptyOne) {
    TwoStructures r;
    EXPECT_EQ(r.state(), State::Inspect) << "the new structure is probed or boxed first";
    EXPECT_FALSE(r.status().hasLevelSet);
    EXPECT_EQ(r.status().seeds, 0);
    ASSERT_EQ(r.status().structures.size(), 2U);
    EXPECT_EQ(r.status().structures[0].info.name, model::kFirstStructureName);
    EXPECT_FALSE(r.status().structures[0].active);
    EXPECT_FALSE(r.status().structures[0].empty);
    EXPECT_GT(r.status().structures[0].volumeMl, 0.0);
    EXPECT_TRUE(r.status().structures[1].active);
    EXPECT_TRUE(r.status().structures[1].empty);
    EXPECT_EQ(r.engine.claimedVoxels(), r.firstVoxels) << "the first is the second's barrier";
    const workflow::StructureList list = r.wf->structures();
    ASSERT_EQ(list.items.size(), 2U);
    EXPECT_EQ(list.items[0].mask.runs, r.firstMask.runs);
    EXPECT_EQ(list.items[0].seeds, 1);
    // The site's colour for a new name comes from the palette; unexported work is guarded.
    EXPECT_NE(list.items[1].info.colour, list.items[0].info.colour);
    EXPECT_FALSE(r.act(model::LoadScan{"other.nii.gz"}).accepted)
        << "the first structure is unexported work though the active one is empty";
}

TEST(WorkflowStructures, ANewStructureCannotGrowIntoAnAcceptedOneUnlessTheConfigAllows) {
    {
        TwoStructures r;
        r.seed({8.0, 6.0, 4.0}, 3.0); // over the first one and beyond it
        EXPECT_GT(r.engine.insideVoxels(), 0U);
        const std::vector<std::uint8_t> first = decodeRuns(r.firstMask);
        const std::vector<std::uint8_t> second = decodeRuns(r.engine.levelSetMask());
        std::size_t both = 0;
        for (std::size_t i = 0; i < first.size(); ++i) {
            both += first[i] != 0 && second[i] != 0 ? 1 : 0;
        }
        EXPECT_EQ(both, 0U) << "overlap refused by default";
    }
    workflow::Settings s = testSettings();
    s.structuresOverlap = true;
    TwoStructures r(s);
    EXPECT_EQ(r.engine.claimedVoxels(), 0U);
    r.seed({8.0, 6.0, 4.0}, 3.0);
    EXPECT_GT(r.engine.insideVoxels(), r.firstVoxels) << "overlap allowed by the config";
}

TEST(WorkflowStructures, SelectingPutsEachSurfaceAndItsParametersBack) {
    TwoStructures r;
    r.seed({3.0, 3.0, 2.0}, 1.5);
    ASSERT_TRUE(r.act(model::SetParam{model::Param::T, 123.0}).accepted);
    const MaskRuns second = r.engine.levelSetMask();
    const std::size_t secondVoxels = r.engine.insideVoxels();
    ASSERT_TRUE(r.act(op(StructureOp::Select, std::string(model::kFirstStructureName))).accepted);
    EXPECT_EQ(r.state(), State::Paused);
    EXPECT_EQ(r.engine.levelSetMask().runs, r.firstMask.runs);
    EXPECT_EQ(r.status().seeds, 1);
    EXPECT_NE(r.status().params.T, 123.0F) << "the first one's T, not the second's";
    EXPECT_EQ(r.engine.claimedVoxels(), secondVoxels);
    ASSERT_TRUE(r.act(op(StructureOp::Select, "Spleen")).accepted);
    EXPECT_EQ(r.engine.levelSetMask().runs, second.runs);
    EXPECT_FLOAT_EQ(r.status().params.T, 123.0F);
    EXPECT_FALSE(r.act(op(StructureOp::Select, "Spleen")).accepted) << "active already";
    EXPECT_FALSE(r.act(op(StructureOp::Select, "Kidney")).accepted) << "no such structure";
}

TEST(WorkflowStructures, UndoAndRedoSpanStructures) {
    TwoStructures r;
    r.seed({3.0, 3.0, 2.0}, 1.5);
    const MaskRuns second = r.engine.levelSetMask();
    ASSERT_TRUE(r.act(model::Undo{}).accepted); // the seed in Spleen
    EXPECT_FALSE(r.status().hasLevelSet);
    ASSERT_TRUE(r.act(model::Undo{}).accepted); // the add
    ASSERT_EQ(r.status().structures.size(), 1U);
    EXPECT_EQ(r.engine.levelSetMask().runs, r.firstMask.runs);
    EXPECT_EQ(r.engine.claimedVoxels(), 0U);
    EXPECT_EQ(r.status().seeds, 1);
    ASSERT_TRUE(r.act(model::Redo{}).accepted);
    ASSERT_TRUE(r.act(model::Redo{}).accepted);
    ASSERT_EQ(r.status().structures.size(), 2U);
    EXPECT_EQ(r.status().structures[1].info.name, "Spleen");
    EXPECT_EQ(r.engine.levelSetMask().runs, second.runs);
    EXPECT_EQ(r.engine.claimedVoxels(), r.firstVoxels);
}

TEST(WorkflowStructures, RenameRecolourHideAndDeleteAreUndoable) {
    TwoStructures r;
    model::EditStructure recolour = op(StructureOp::Recolour, "Spleen");
    recolour.colour = {0.1, 0.2, 0.3};
    ASSERT_TRUE(r.act(recolour).accepted);
    ASSERT_TRUE(r.act(op(StructureOp::Rename, "Spleen", "Left kidney")).accepted);
    ASSERT_TRUE(r.act(op(StructureOp::Hide, std::string(model::kFirstStructureName))).accepted);
    EXPECT_FALSE(r.status().structures[0].info.visible);
    EXPECT_EQ(r.status().structures[1].info.name, "Left kidney");
    EXPECT_EQ(r.status().structures[1].info.colour, glm::dvec3(0.1, 0.2, 0.3));
    ASSERT_TRUE(r.act(model::Undo{}).accepted);
    EXPECT_TRUE(r.status().structures[0].info.visible);
    ASSERT_TRUE(r.act(model::Undo{}).accepted);
    EXPECT_EQ(r.status().structures[1].info.name, "Spleen");
    ASSERT_TRUE(r.act(model::Redo{}).accepted);
    EXPECT_EQ(r.status().structures[1].info.name, "Left kidney");
    // Refusals: a taken name, a bad one, a colour out of range, the last structure.
    EXPECT_FALSE(
        r.act(op(StructureOp::Rename, "Left kidney", std::string(model::kFirstStructureName)))
            .accepted);
    EXPECT_FALSE(r.act(op(StructureOp::Add, "a|b")).accepted);
    EXPECT_FALSE(r.act(op(StructureOp::Add, "")).accepted);
    EXPECT_FALSE(r.act(op(StructureOp::Add, "Left kidney")).accepted);
    recolour.name = "Left kidney";
    recolour.colour = {2.0, 0.0, 0.0};
    EXPECT_FALSE(r.act(recolour).accepted);
    // Deleting the active one makes the one before it active, its surface back.
    ASSERT_TRUE(r.act(op(StructureOp::Delete, "Left kidney")).accepted);
    ASSERT_EQ(r.status().structures.size(), 1U);
    EXPECT_EQ(r.engine.levelSetMask().runs, r.firstMask.runs);
    EXPECT_EQ(r.state(), State::Paused);
    EXPECT_FALSE(r.act(op(StructureOp::Delete, std::string(model::kFirstStructureName))).accepted)
        << "the only structure stays";
    ASSERT_TRUE(r.act(model::Undo{}).accepted);
    ASSERT_EQ(r.status().structures.size(), 2U);
    EXPECT_TRUE(r.status().structures[1].active);
}

TEST(WorkflowStructures, AnExportGetsEveryStructureWithASurfaceNumberedInOrder) {
    TwoStructures r;
    r.seed({3.0, 3.0, 2.0}, 1.5);
    const MaskRuns second = r.engine.levelSetMask();
    ASSERT_TRUE(r.act(op(StructureOp::Add, "Empty one")).accepted);
    ASSERT_TRUE(r.act(model::Finish{}).accepted) << "the others have surfaces to review";
    const auto exported = r.act(model::Export{"out.dcm"});
    ASSERT_TRUE(exported.accepted) << exported.reason;
    ASSERT_EQ(r.engine.exportedStructures.size(), 2U) << "the empty one has no segment";
    EXPECT_EQ(r.engine.exportedStructures[0].name, model::kFirstStructureName);
    EXPECT_EQ(r.engine.exportedStructures[0].label, 1);
    EXPECT_EQ(r.engine.exportedStructures[0].mask.runs, r.firstMask.runs);
    EXPECT_EQ(r.engine.exportedStructures[1].name, "Spleen");
    EXPECT_EQ(r.engine.exportedStructures[1].label, 2);
    EXPECT_EQ(r.engine.exportedStructures[1].mask.runs, second.runs);
}

TEST(WorkflowStructures, ReviewMeasuresEveryStructureWithASurface) {
    TwoStructures r;
    r.seed({3.0, 3.0, 2.0}, 1.5);
    const std::size_t second = r.engine.insideVoxels();
    ASSERT_TRUE(r.act(model::Finish{}).accepted);
    ASSERT_EQ(r.status().measurements.size(), 2U);
    EXPECT_EQ(r.status().measurements[0].name, model::kFirstStructureName);
    EXPECT_EQ(r.status().measurements[0].measured.voxels, r.firstVoxels);
    EXPECT_EQ(r.status().measurements[1].measured.voxels, second);
    ASSERT_TRUE(r.act(op(StructureOp::Hide, "Spleen")).accepted);
    EXPECT_FALSE(r.status().measurements[1].visible) << "a hidden one draws no lines";
    // Renamed and recoloured in review: the table follows, the figures stay the structure's,
    // and hiding it by its new name still reaches its lines.
    ASSERT_TRUE(r.act(op(StructureOp::Show, "Spleen")).accepted);
    ASSERT_TRUE(r.act(op(StructureOp::Rename, "Spleen", "Left kidney")).accepted);
    model::EditStructure recolour = op(StructureOp::Recolour, "Left kidney");
    recolour.colour = {0.2, 0.4, 0.6};
    ASSERT_TRUE(r.act(recolour).accepted);
    EXPECT_EQ(r.status().measurements[1].name, "Left kidney");
    EXPECT_EQ(r.status().measurements[1].colour, recolour.colour);
    EXPECT_EQ(r.status().measurements[1].measured.voxels, second);
    ASSERT_TRUE(r.act(op(StructureOp::Hide, "Left kidney")).accepted);
    EXPECT_FALSE(r.status().measurements[1].visible);
    ASSERT_TRUE(r.act(model::Resume{}).accepted);
    EXPECT_TRUE(r.status().measurements.empty()) << "steering may change them";
}

TEST(WorkflowStructures, ASessionOfItsFirstStructureExportsAsBefore) {
    Rig r;
    r.load();
    r.seed();
    ASSERT_TRUE(r.act(model::Finish{}).accepted);
    const auto exported = r.act(model::Export{"out.nii.gz"});
    ASSERT_TRUE(exported.accepted) << exported.reason;
    EXPECT_TRUE(r.engine.exportedStructures.empty());
    EXPECT_EQ(r.engine.exports.size(), 1U);
}

TEST(WorkflowStructures, TheSiteListGivesANameItsCodesAndTheAuditNamesTheStructure) {
    workflow::Settings s = testSettings();
    model::StructureInfo liver{"Liver",
                               {"123037004", "SCT", "Anatomical Structure"},
                               {"10200004", "SCT", "Liver"},
                               {0.8, 0.5, 0.4},
                               true};
    s.structureKinds = {liver};
    const auto path = std::filesystem::path(testing::TempDir()) / "structures-audit.jsonl";
    std::filesystem::remove(path);
    workflow::AuditLog log(path, fixedTime);
    Rig r(s, &log);
    r.load();
    r.seed();
    ASSERT_TRUE(r.act(op(StructureOp::Add, "liver")).accepted);
    const workflow::StructureList list = r.wf->structures();
    EXPECT_EQ(list.items[1].info.type, liver.type) << "matched without case";
    EXPECT_EQ(list.items[1].info.colour, liver.colour);
    EXPECT_EQ(list.items[1].info.name, "liver") << "the operator's own spelling";
    // Renamed, the first structure takes the site's code for its new name, and free text
    // takes tissue's again; the colour is the operator's.
    const std::string first(model::kFirstStructureName);
    ASSERT_TRUE(r.act(op(StructureOp::Delete, "liver")).accepted);
    ASSERT_TRUE(r.act(op(StructureOp::Rename, first, "LIVER")).accepted);
    EXPECT_EQ(r.wf->structures().items[0].info.type, liver.type);
    EXPECT_NE(r.wf->structures().items[0].info.colour, liver.colour);
    ASSERT_TRUE(r.act(op(StructureOp::Rename, "LIVER", first)).accepted);
    EXPECT_EQ(r.wf->structures().items[0].info.type, model::tissueCode());
    ASSERT_TRUE(r.act(model::Undo{}).accepted);
    ASSERT_TRUE(r.act(model::Undo{}).accepted);
    ASSERT_TRUE(r.act(model::Undo{}).accepted);
    ASSERT_EQ(r.wf->structures().items.size(), 2U);
    r.seed({3.0, 3.0, 2.0}, 1.5);
    const workflow::AuditLogContents contents = workflow::readAuditLog(path);
    std::vector<std::string> named;
    for (const nlohmann::json& rec : contents.records) {
        if (rec.at("event") == "action" && rec.at("action") == "add_seed") {
            named.push_back(rec.at("structure").get<std::string>());
        }
    }
    EXPECT_EQ(named, (std::vector<std::string>{std::string(model::kFirstStructureName), "liver"}));
}

TEST(WorkflowStructures, SiteKindsWithoutValidCodesOrTwiceNamedAreRefused) {
    workflow::Settings s = testSettings();
    s.structureKinds = {{"Liver", {"", "SCT", "Anatomical Structure"}, model::tissueCode()}};
    EXPECT_THROW(workflow::validateSettings(s), std::invalid_argument);
    s.structureKinds = {{"Liver"}, {"Liver"}};
    EXPECT_THROW(workflow::validateSettings(s), std::invalid_argument);
    s.structureKinds = {{"Liver"}};
    EXPECT_NO_THROW(workflow::validateSettings(s));
}

TEST(WorkflowStructures, AResumeBringsEveryStructureBackAndRefusesAGarbledList) {
    TwoStructures r;
    r.seed({3.0, 3.0, 2.0}, 1.5);
    workflow::StructureList saved = r.wf->structures();
    saved.items[1].mask = r.engine.levelSetMask(); // as the autosave keeps the active one's
    const MaskRuns active = saved.items[1].mask;
    saved.items[1].mask = {};

    Rig fresh;
    fresh.load();
    fresh.engine.setMask(active);
    workflow::RestoredSession restored;
    restored.state = State::Paused;
    restored.seeds = 1;
    restored.structures = saved;
    ASSERT_TRUE(fresh.wf->restoreSession(restored).accepted);
    ASSERT_EQ(fresh.status().structures.size(), 2U);
    EXPECT_EQ(fresh.wf->structures().items[0].mask.runs, r.firstMask.runs);
    EXPECT_EQ(fresh.engine.claimedVoxels(), r.firstVoxels);

    Rig garbled;
    garbled.load();
    saved.items[1].info.name = saved.items[0].info.name;
    restored.structures = saved;
    EXPECT_FALSE(garbled.wf->restoreSession(restored).accepted);
}

} // namespace
} // namespace steerseg::test
