// The structures section of the panel model (PanelModel::structures, newStructures): a row per
// structure (select, show or hide, delete), the active one's Rename and Colour with the
// palette while open, and a button per kind not yet taken plus a free "Structure N".
#include "model/structure.hpp"
#include "ui/panel_model.hpp"

#include <algorithm>
#include <cstdio>

namespace steerseg::ui {

using model::ActionKind;

namespace {

// The active structure's Rename and Colour, and the palette's swatches while they are open.
// The buttons only open the panel's editors; what they complete goes to the workflow, which
// decides (a name it refuses keeps the keyboard open with the reason).
void addStructureTools(const workflow::StructureRow& active, bool can, const PanelEditors& open,
                       PanelModel& m) {
    const std::string& name = active.info.name;
    m.structureTools.push_back(
        {"Rename##structure",
         model::EditStructure{model::StructureOp::Rename, name, name, glm::dvec3(0.0)}, open.rename,
         can, Completion::Name});
    m.structureTools.push_back(
        {"Colour##structure",
         model::EditStructure{model::StructureOp::Recolour, name, {}, active.info.colour},
         open.colours, can, Completion::Colour, active.info.colour});
    if (!open.colours) {
        return;
    }
    // The swatches are the palette's whole cycle (paletteColour starts again after it).
    std::size_t swatches = 1;
    while (swatches < model::kMaxStructures &&
           model::paletteColour(swatches) != model::paletteColour(0)) {
        ++swatches;
    }
    for (std::size_t i = 0; i < swatches; ++i) {
        const glm::dvec3 colour = model::paletteColour(i);
        m.colours.push_back({"##colour" + std::to_string(i),
                             model::EditStructure{model::StructureOp::Recolour, name, {}, colour},
                             colour == active.info.colour, can, Completion::None, colour});
    }
}

// The structures' list (docs/structures.md): touch alone adds, selects, hides, deletes, renames
// (the on-screen keyboard) and recolours (the palette).
} // namespace

void addStructures(const workflow::Status& st, const PanelEditors& open, PanelModel& m) {
    const bool can = st.allowed.contains(ActionKind::EditStructure);
    const auto edit = [](model::StructureOp op, const std::string& name) {
        return model::EditStructure{op, name, {}, glm::dvec3(0.0)};
    };
    for (std::size_t i = 0; i < st.structures.size(); ++i) {
        const workflow::StructureRow& r = st.structures[i];
        const std::string id = "##structure" + std::to_string(i);
        char volume[32];
        std::snprintf(volume, sizeof volume, "%.1f ml", r.volumeMl);
        m.structures.push_back(
            {r.info.name + (r.empty ? "  (empty)" : "  " + std::string(volume)) + id,
             edit(model::StructureOp::Select, r.info.name), r.active, can && !r.active});
        m.structures.push_back(
            {(r.info.visible ? "Hide" : "Show") + id,
             edit(r.info.visible ? model::StructureOp::Hide : model::StructureOp::Show,
                  r.info.name),
             !r.info.visible, can});
        m.structures.push_back({"Delete" + id, edit(model::StructureOp::Delete, r.info.name), false,
                                can && st.structures.size() > 1});
        if (r.active) {
            addStructureTools(r, can, open, m);
        }
    }
    const auto taken = [&](const std::string& name) {
        return std::any_of(st.structures.begin(), st.structures.end(),
                           [&](const workflow::StructureRow& r) { return r.info.name == name; });
    };
    for (const std::string& kind : st.structureKinds) {
        if (!taken(kind)) {
            m.newStructures.push_back(
                {"+ " + kind + "##new", edit(model::StructureOp::Add, kind), false, can});
        }
    }
    std::size_t n = st.structures.size() + 1;
    while (taken("Structure " + std::to_string(n))) {
        ++n;
    }
    const std::string free = "Structure " + std::to_string(n);
    m.newStructures.push_back(
        {"+ " + free + "##new", edit(model::StructureOp::Add, free), false, can});
}

} // namespace steerseg::ui
