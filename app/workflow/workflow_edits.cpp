// The level set: seed and erase spheres, restart, and undo/redo of every edit. A sphere edit is
// recorded as snapshots of the level set before and after it (none for an empty level set), so
// undo and redo are exact whatever evolved in between; the undo stack frees what it drops.
#include "workflow/one_line.hpp"
#include "workflow/workflow.hpp"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <sstream>

namespace steerseg::workflow {

namespace {

bool finite(const glm::dvec3& v) {
    return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

} // namespace

void Workflow::refreshEngineStatus() {
    status_.hasLevelSet = engine_.hasLevelSet();
    const model::SolverStats s = engine_.stats();
    status_.iterations = s.iterations;
    status_.evolvedTime = static_cast<double>(s.evolvedTime);
    status_.volumeMl =
        status_.state == model::State::Evolving ? engine_.volumeMl() : engine_.exactVolumeMl();
    showStructures();
}

void Workflow::refreshUndoFlags() {
    status_.canUndo = undo_.undoTop() != nullptr;
    status_.canRedo = undo_.redoTop() != nullptr;
}

void Workflow::afterLevelSetChange() {
    eraseWatch_.reset(); // the surface it would go back to is not this one's
    liftWithdrawLimit(); // nor is the one it keeps the depth of
    dirty_ = true;
    status_.converged = false;
    refreshEngineStatus();
}

LevelSetMark Workflow::markNow(int seeds, int erasures) {
    LevelSetMark m;
    m.seeds = seeds;
    m.erasures = erasures;
    if (engine_.hasLevelSet()) {
        m.snapshot = engine_.snapshot();
    }
    return m;
}

void Workflow::restoreMark(const LevelSetMark& mark) {
    if (mark.snapshot) {
        engine_.restore(*mark.snapshot);
    } else {
        engine_.clearLevelSet();
    }
    status_.seeds = mark.seeds;
    status_.erasures = mark.erasures;
}

void Workflow::releaseSnapshot(const std::optional<SnapshotId>& id) {
    if (id) {
        try {
            engine_.drop(*id);
        } catch (...) {
            // Nothing the operator can do about it; the engine keeps the copy.
        }
    }
}

void Workflow::editLevelSet(
    std::string_view what, const std::function<void()>& edit, int seeds, int erasures,
    const ParamValues* params,
    std::pair<std::shared_ptr<const StructureList>, std::shared_ptr<const StructureList>>
        structures) {
    const LevelSetMark before = markNow(status_.seeds, status_.erasures);
    try {
        edit();
    } catch (...) {
        // An edit of many spheres (a stroke) may fail part way: none of it stays.
        try {
            restoreMark(before);
        } catch (...) {
        }
        releaseSnapshot(before.snapshot);
        refreshEngineStatus();
        throw;
    }
    LevelSetMark after;
    try {
        after = markNow(seeds, erasures);
    } catch (...) {
        // Without a copy of the result the edit could not be redone: take it back.
        try {
            restoreMark(before);
        } catch (...) {
        }
        releaseSnapshot(before.snapshot);
        afterLevelSetChange();
        throw;
    }
    UndoEntry e;
    e.what = what;
    e.levelSet = true;
    e.paramsBefore = params_;
    if (params != nullptr) {
        applyEditParams(clamped(*params));
    }
    e.paramsAfter = params_;
    e.before = before;
    e.after = after;
    e.structuresBefore = std::move(structures.first);
    e.structuresAfter = std::move(structures.second);
    undo_.push(std::move(e));
    status_.seeds = seeds;
    status_.erasures = erasures;
    afterLevelSetChange();
}

void Workflow::applyEditParams(const ParamValues& values) {
    if (values == params_) {
        return;
    }
    try {
        applyParams(values);
    } catch (const std::exception& e) {
        // The level set has moved already: the edit, undo or redo stands, the speed stays as it
        // was (classify did not learn from a seed, say).
        status_.message = "the surface changed, but the speed stayed: " + oneLine(e.what());
    }
}

std::string Workflow::sphereProblem(const glm::dvec3& voxel, double radius) const {
    if (!finite(voxel) || !std::isfinite(radius)) {
        return "a sphere needs a finite centre and radius";
    }
    const glm::ivec3 dims = status_.scan.dims;
    for (int a = 0; a < 3; ++a) {
        if (voxel[a] < 0.0 || voxel[a] > static_cast<double>(dims[a] - 1)) {
            std::ostringstream msg;
            msg << "sphere centre (" << voxel.x << ", " << voxel.y << ", " << voxel.z
                << ") lies outside the scan (" << dims.x << " x " << dims.y << " x " << dims.z
                << " voxels)";
            return msg.str();
        }
    }
    return {};
}

model::Sphere Workflow::brushSphere(const glm::dvec3& voxel, double radius) const {
    const ParamRange& r = status_.ranges[indexOf(model::Param::Radius)];
    const double rad =
        radius > 0.0 ? clampTo(r, radius) : params_.values[indexOf(model::Param::Radius)];
    return {glm::vec3(voxel), static_cast<float>(rad)};
}

std::string Workflow::stickyEdit(const model::Sphere& sphere, bool seed,
                                 const std::optional<model::TissueLevel>& tissue) {
    if (seed) {
        engine_.addSeed(sphere);
    } else {
        engine_.erase(sphere);
    }
    if (engine_.addBarrier({sphere, seed, tissue})) {
        return {};
    }
    return std::string(seed ? "added; the front may leave it again: "
                            : "erased; the front may grow back there: ") +
           std::to_string(engine_.barriers()) + " corrections hold already (restart to clear them)";
}

std::optional<model::TissueLevel> Workflow::tissueLevel(const model::Sphere& sphere) const {
    // The window reaches as far as a correction's run may move the surface; with runs
    // everywhere (a reach of 0) there is none: a window without bound is the global widening
    // that leaked.
    const double reach = std::min(settings_.correctionReach * static_cast<double>(sphere.radius),
                                  glm::length(glm::dvec3(status_.scan.dims)));
    if (reach <= 0.0) {
        return std::nullopt;
    }
    // The sphere in mm (its radius counts voxels along the finest axis: model::Sphere).
    const glm::dvec3& spacing = status_.scan.spacing;
    const double radiusMm =
        static_cast<double>(sphere.radius) * std::min({spacing.x, spacing.y, spacing.z});
    const ProbeResult p = engine_.measure(glm::dvec3(sphere.centre), radiusMm);
    if (p.count == 0 || !std::isfinite(p.mean)) {
        return std::nullopt; // the seed still keeps its sphere
    }
    return model::TissueLevel{static_cast<float>(p.mean), static_cast<float>(reach)};
}

Workflow::Outcome Workflow::sphereEdit(const glm::dvec3& voxel, double radius, bool seed) {
    if (std::string problem = sphereProblem(voxel, radius); !problem.empty()) {
        return no(std::move(problem));
    }
    if (!seed && !status_.hasLevelSet) {
        return no("nothing to erase");
    }
    const model::Sphere sphere = brushSphere(voxel, radius);
    // Once the front has run, an edit corrects it (docs/steering.md): the surface should follow
    // the operator from then on, not undo the edit a few iterations later.
    const bool correcting =
        status_.state == model::State::Evolving || status_.state == model::State::Paused;
    ParamValues next = params_;
    if (seed) {
        holdInBox(next, sphere);
    }
    if (correcting) {
        // A correction is an example of its class for as long as it stands, as a stroke's dabs
        // are: among the newest taps it would drop out after six, and a sarcoma's leak came
        // back when its first erases did (docs/steering.md). T and eps stay: widening them to
        // a seed's tissue let a real liver's front leak, and one seed should not undo what the
        // others reached; the seed's barrier teaches the window locally instead.
        addPainted(seed ? next.speed.paintedInside : next.speed.paintedOutside, {sphere});
    } else if (seed) {
        // The operator puts seeds in the structure, often where no probe was: classify's inside
        // examples too, as on the command line (docs/speed.md).
        addExample(next.speed.inside, sphere);
    }
    // A seed while correcting marks tissue the window at T missed (docs/steering.md).
    const std::optional<model::TissueLevel> tissue =
        seed && correcting ? tissueLevel(sphere) : std::nullopt;
    std::string notice;
    editLevelSet(
        seed ? "add_seed" : "erase",
        [&] {
            if (correcting) {
                notice = stickyEdit(sphere, seed, tissue);
            } else if (seed) {
                engine_.addSeed(sphere);
            } else {
                engine_.erase(sphere);
            }
        },
        status_.seeds + (seed ? 1 : 0), status_.erasures + (seed ? 0 : 1), &next);
    if (!notice.empty()) {
        status_.message = notice;
    }
    if (correcting && !status_.hasLevelSet) {
        const std::string empty = "the level set is empty: add a seed";
        if (status_.state == model::State::Evolving) {
            enter(model::State::Paused, empty);
        } else {
            status_.message = empty; // not the stop's message of the surface now gone
        }
    }
    return ok();
}

Workflow::Outcome Workflow::on(const model::AddSeed& a) {
    return sphereEdit(a.voxel, a.radius, true);
}

Workflow::Outcome Workflow::on(const model::Erase& a) {
    return sphereEdit(a.voxel, a.radius, false);
}

Workflow::Outcome Workflow::on(const model::SetEraseMode& a) {
    status_.eraseMode = a.erase;
    if (a.erase) {
        status_.outsideMode = false; // one meaning per tap
        status_.boxMode = false;
        status_.boxFace.reset();
    }
    return ok();
}

Workflow::Outcome Workflow::on(const model::Restart&) {
    erasesCreep_ = false;
    editLevelSet(
        "restart", [&] { engine_.clearLevelSet(); }, 0, 0);
    return ok();
}

Workflow::Outcome Workflow::on(const model::Undo&) {
    const UndoEntry* e = undo_.undoTop();
    if (e == nullptr) {
        return no("nothing to undo");
    }
    lastUndone_ = e->what;
    if (e->levelSet) {
        restoreMark(e->before);
        putStructures(e->structuresBefore);
        afterLevelSetChange();
        applyEditParams(e->paramsBefore); // what came with the edit (a seed's inside example)
    } else {
        putStructures(e->structuresBefore);
        applyParams(e->paramsBefore);
    }
    undo_.undone();
    return ok();
}

Workflow::Outcome Workflow::on(const model::Redo&) {
    const UndoEntry* e = undo_.redoTop();
    if (e == nullptr) {
        return no("nothing to redo");
    }
    lastUndone_ = e->what;
    if (e->levelSet) {
        restoreMark(e->after);
        putStructures(e->structuresAfter);
        afterLevelSetChange();
        applyEditParams(e->paramsAfter);
    } else {
        putStructures(e->structuresAfter);
        applyParams(e->paramsAfter);
    }
    undo_.redone();
    return ok();
}

} // namespace steerseg::workflow
