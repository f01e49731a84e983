// The session's structures (docs/structures.md): add, select, rename, recolour, show, hide and
// delete, each one undo step. The active structure is the engine's level set; leaving it keeps
// its surface as a mask, with the parameters and counts it had, and coming back puts both back.
// The others are the engine's claimed voxels unless the config lets structures overlap.
#include "workflow/one_line.hpp"
#include "workflow/workflow.hpp"

#include <cmath>
#include <utility>

namespace steerseg::workflow {

namespace {

double millilitres(const MaskRuns& mask, const glm::dvec3& spacing) {
    std::uint64_t inside = 0;
    for (std::size_t r = 1; r < mask.runs.size(); r += 2) {
        inside += mask.runs[r];
    }
    return static_cast<double>(inside) * spacing.x * spacing.y * spacing.z / 1000.0;
}

std::size_t voxelsOf(const ScanInfo& scan) {
    return static_cast<std::size_t>(scan.dims.x) * static_cast<std::size_t>(scan.dims.y) *
           static_cast<std::size_t>(scan.dims.z);
}

} // namespace

StructureList Workflow::structures() const {
    StructureList out = structures_;
    if (out.active < out.items.size()) {
        out.items[out.active].params = params_;
        out.items[out.active].seeds = status_.seeds;
        out.items[out.active].erasures = status_.erasures;
        out.items[out.active].volumeMl = status_.volumeMl;
    }
    return out;
}

void Workflow::firstStructure() {
    structures_ = {};
    Structure first;
    first.info = model::structureFor(model::kFirstStructureName, settings_.structureKinds, 0);
    structures_.items.push_back(std::move(first));
    ++structuresVersion_;
    claimOthers(structures_);
    showStructures();
}

void Workflow::showStructures() {
    // Measurements live only in review, where the list keeps its order (adding, selecting and
    // deleting leave review): the figures stay, the description follows the structure's.
    for (StructureMeasured& m : status_.measurements) {
        if (m.structure < structures_.items.size()) {
            const model::StructureInfo& info = structures_.items[m.structure].info;
            m.name = info.name;
            m.colour = info.colour;
            m.visible = info.visible; // hidden in review: no lines
        }
    }
    status_.structures.clear();
    for (std::size_t i = 0; i < structures_.items.size(); ++i) {
        const Structure& s = structures_.items[i];
        const bool active = i == structures_.active;
        status_.structures.push_back({s.info, active ? status_.volumeMl : s.volumeMl, active,
                                      active ? !status_.hasLevelSet : s.mask.runs.empty()});
    }
}

void Workflow::measureStructures() {
    status_.measurements.clear();
    for (std::size_t i = 0; i < structures_.items.size(); ++i) {
        const Structure& s = structures_.items[i];
        const bool active = i == structures_.active;
        if (active ? !engine_.hasLevelSet() : s.mask.runs.empty()) {
            continue;
        }
        try {
            status_.measurements.push_back({i, s.info.name, s.info.colour, s.info.visible,
                                            engine_.measureStructure(active ? nullptr : &s.mask)});
        } catch (const std::exception&) {
            // The surface is shown and exported whatever its figures: the table goes without.
        }
    }
}

Structure Workflow::leaveActive() const {
    Structure s = structures_.items.at(structures_.active);
    s.mask = engine_.hasLevelSet() ? engine_.levelSetMask() : MaskRuns{};
    s.params = params_;
    s.seeds = status_.seeds;
    s.erasures = status_.erasures;
    s.volumeMl = millilitres(s.mask, status_.scan.spacing);
    return s;
}

void Workflow::claimOthers(const StructureList& list) {
    engine_.setClaimed(settings_.structuresOverlap
                           ? MaskRuns{}
                           : claimedBy(list, list.active, voxelsOf(status_.scan)));
}

void Workflow::putStructures(const std::shared_ptr<const StructureList>& list) {
    if (!list) {
        return;
    }
    structures_ = *list;
    ++structuresVersion_;
    claimOthers(structures_);
    showStructures();
}

Workflow::Outcome Workflow::on(const model::EditStructure& a) {
    if (a.op == model::StructureOp::Add) {
        return addStructure(a.name);
    }
    const std::optional<std::size_t> index = structures_.find(a.name);
    if (!index) {
        return no("no structure named '" + a.name + "'");
    }
    switch (a.op) {
    case model::StructureOp::Select:
        if (*index == structures_.active) {
            return no("'" + a.name + "' is the active structure already");
        }
        return selectStructure(*index, "select_structure");
    case model::StructureOp::Delete:
        return deleteStructure(*index);
    default:
        return describeStructure(a, *index);
    }
}

Workflow::Outcome Workflow::addStructure(const std::string& name) {
    if (std::string problem = model::structureNameProblem(name); !problem.empty()) {
        return no(std::move(problem));
    }
    if (structures_.find(name)) {
        return no("a structure named '" + name + "' exists already");
    }
    if (structures_.items.size() >= model::kMaxStructures) {
        return no("a session holds at most " + std::to_string(model::kMaxStructures) +
                  " structures");
    }
    auto before = std::make_shared<const StructureList>(structures());
    StructureList next = *before;
    next.items[next.active] = leaveActive();
    Structure added;
    added.info = model::structureFor(name, settings_.structureKinds, next.items.size());
    next.items.push_back(std::move(added));
    next.active = next.items.size() - 1;
    auto after = std::make_shared<const StructureList>(next);
    // The new structure starts as a new scan's level set does: its own probe, seeds and speed;
    // the brush stays the operator's.
    ParamValues fresh = defaultParams();
    fresh.values[indexOf(model::Param::Radius)] = params_.values[indexOf(model::Param::Radius)];
    erasesCreep_ = false;
    editLevelSet("add_structure",
                 [&] {
                     engine_.clearLevelSet();
                     claimOthers(next);
                 },
                 0, 0, &fresh, {before, after});
    putStructures(after);
    enter(model::State::Inspect, "structure '" + name + "': probe it, draw its box or seed it");
    return ok();
}

Workflow::Outcome Workflow::selectStructure(std::size_t index, std::string_view what) {
    auto before = std::make_shared<const StructureList>(structures());
    StructureList next = *before;
    if (structures_.active < next.items.size()) {
        next.items[next.active] = leaveActive();
    }
    Structure target = next.items.at(index);
    next.items[index].mask = {}; // the engine's level set holds it from now on
    next.active = index;
    auto after = std::make_shared<const StructureList>(next);
    erasesCreep_ = false;
    editLevelSet(what,
                 [&] {
                     engine_.setMask(target.mask);
                     claimOthers(next);
                 },
                 target.seeds, target.erasures, &target.params, {before, after});
    putStructures(after);
    if (status_.hasLevelSet) {
        enter(model::State::Paused, "structure '" + target.info.name + "'");
    } else {
        enter(model::State::Inspect, "structure '" + target.info.name + "' has no surface yet");
    }
    return ok();
}

Workflow::Outcome Workflow::deleteStructure(std::size_t index) {
    if (structures_.items.size() == 1) {
        return no("the session's only structure cannot be deleted: restart clears it");
    }
    if (index != structures_.active) {
        auto before = std::make_shared<const StructureList>(structures());
        StructureList next = *before;
        next.items.erase(next.items.begin() + static_cast<std::ptrdiff_t>(index));
        if (next.active > index) {
            --next.active;
        }
        auto after = std::make_shared<const StructureList>(next);
        // The level set stays; only what it may grow into changes.
        editLevelSet("delete_structure", [&] { claimOthers(next); }, status_.seeds,
                     status_.erasures, nullptr, {before, after});
        putStructures(after);
        return ok();
    }
    // The active one: the one before it (or after the first) becomes active, the deleted one's
    // surface is dropped with it. Select first, then take the old one out of that entry's list.
    const std::size_t successor = index > 0 ? index - 1 : 1;
    auto before = std::make_shared<const StructureList>(structures());
    StructureList next = *before;
    Structure target = next.items.at(successor);
    next.items.erase(next.items.begin() + static_cast<std::ptrdiff_t>(index));
    next.active = successor > index ? successor - 1 : successor;
    next.items[next.active].mask = {};
    auto after = std::make_shared<const StructureList>(next);
    erasesCreep_ = false;
    editLevelSet("delete_structure",
                 [&] {
                     engine_.setMask(target.mask);
                     claimOthers(next);
                 },
                 target.seeds, target.erasures, &target.params, {before, after});
    putStructures(after);
    enter(status_.hasLevelSet ? model::State::Paused : model::State::Inspect,
          "structure '" + target.info.name + "'");
    return ok();
}

Workflow::Outcome Workflow::describeStructure(const model::EditStructure& a, std::size_t index) {
    StructureList next = structures_;
    model::StructureInfo& info = next.items[index].info;
    switch (a.op) {
    case model::StructureOp::Rename:
        if (std::string problem = model::structureNameProblem(a.to); !problem.empty()) {
            return no(std::move(problem));
        }
        if (a.to != a.name && structures_.find(a.to)) {
            return no("a structure named '" + a.to + "' exists already");
        }
        info.name = a.to;
        {
            // The code follows the name: a structure renamed to one of the site's kinds is
            // exported as that kind, one renamed to free text as tissue. The colour stays.
            const model::StructureInfo kind =
                model::structureFor(a.to, settings_.structureKinds, index);
            info.category = kind.category;
            info.type = kind.type;
        }
        break;
    case model::StructureOp::Recolour:
        for (int c = 0; c < 3; ++c) {
            if (!(a.colour[c] >= 0.0 && a.colour[c] <= 1.0)) {
                return no("a colour's r, g and b lie within 0..1");
            }
        }
        info.colour = a.colour;
        break;
    case model::StructureOp::Show:
    case model::StructureOp::Hide:
        info.visible = a.op == model::StructureOp::Show;
        break;
    default:
        return no("not a change of a structure's description");
    }
    if (next.items[index].info == structures_.items[index].info) {
        return ok(); // nothing changed: no undo step
    }
    UndoEntry e;
    e.what = "edit_structure";
    e.paramsBefore = params_;
    e.paramsAfter = params_;
    e.structuresBefore = std::make_shared<const StructureList>(structures_);
    e.structuresAfter = std::make_shared<const StructureList>(next);
    putStructures(e.structuresAfter);
    undo_.push(std::move(e));
    return ok();
}

} // namespace steerseg::workflow
