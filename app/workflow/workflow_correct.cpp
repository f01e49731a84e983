// The operator's correction (model::Correct): the clicks protocol's unit (docs/steering.md). The
// first one, on a scan without a level set, does what an operator's first taps do: probe
// there (T and eps from the tissue), seed there; a later one is the seed or the erase of a tap
// in add or remove mode while steering (workflow_edits.cpp: either then sticks), and its run
// reaches only around it.
#include "workflow/workflow.hpp"

#include <cmath>
#include <exception>
#include <glm/geometric.hpp>
#include <sstream>

namespace steerseg::workflow {

std::string Workflow::correctionRadiusProblem(double radius) const {
    const ParamRange& r = status_.ranges[indexOf(model::Param::Radius)];
    if (!(radius <= 0.0) && !(radius >= r.min && radius <= r.max)) {
        std::ostringstream msg;
        msg << "a correction's radius of " << radius << " voxels lies outside the brush's range ["
            << r.min << ", " << r.max << "] on this scan";
        return msg.str();
    }
    return {};
}

Workflow::Outcome Workflow::on(const model::Correct& a) {
    if (!status_.hasLevelSet) {
        return first(a);
    }
    // Before the first run the surface is the seeds' alone: nothing to keep as it is.
    const bool steering =
        status_.state == model::State::Evolving || status_.state == model::State::Paused;
    const SpeedChoice speedBefore = engineSpeed_;
    const double volumeBeforeMl = status_.volumeMl;
    const std::string messageBefore = status_.message;
    Outcome out = sphereEdit(a.voxel, a.radius, a.positive);
    if (!out.accepted || !steering || !status_.hasLevelSet) {
        return out;
    }
    // The table then runs the solver from the surface this leaves. An erase that changed the
    // speed (classify learning from its sphere) changed it everywhere: its run is global, so
    // that the tissue it names leaves the surface wherever it lies, and watched, since the
    // same run goes on advancing wherever the speed allows. An added part is missing where it
    // was put: its run stays around it though the speed learnt from it too.
    const model::Sphere brush = brushSphere(a.voxel, a.radius);
    if (engineSpeed_ == speedBefore || a.positive) {
        reachAround(brush);
    } else if (erasesCreep_) {
        // An earlier erase's run crept under the same T, eps, alpha and kind of speed: this
        // one's would spend its steps up to the limit first, and go back all the same.
        reachAround(brush, true);
        limitWithdrawal(brush);
        ++status_.erasesWithdrawOnly;
        if (status_.message == messageBefore) { // the edit's own notice comes first
            status_.message = "erased; an earlier erase's run crept under this speed: away from "
                              "this one the surface only withdraws";
        }
    } else {
        watchEraseRun(brush, volumeBeforeMl);
        limitWithdrawal(brush);
    }
    return out;
}

std::optional<model::Sphere> Workflow::reachOf(const model::Sphere& brush) const {
    const double radius = settings_.correctionReach * static_cast<double>(brush.radius);
    if (radius <= 0.0 || radius >= glm::length(glm::dvec3(status_.scan.dims))) {
        return std::nullopt;
    }
    return model::Sphere{brush.centre, static_cast<float>(radius)};
}

void Workflow::reachAround(const model::Sphere& brush, bool recedeOutside) {
    const std::optional<model::Sphere> sphere = reachOf(brush);
    if (!sphere) {
        endReach();
        return;
    }
    const model::Reach reach{*sphere, recedeOutside};
    try {
        engine_.setReach(reach);
        reach_ = reach;
    } catch (const std::exception&) {
        // The edit stands; its run then moves the whole surface, as before reaches.
        endReach();
    }
}

// What the erase names may look like the structure's own tissue, which then leaves the surface
// wherever it lies; a leak lies at the surface, the structure's tissue deep in it: beyond the
// reach the run takes back no more than the surface's outer eraseWithdrawMm.
void Workflow::limitWithdrawal(const model::Sphere& brush) {
    const std::optional<model::Sphere> around = reachOf(brush);
    if (settings_.eraseWithdrawMm <= 0.0 || !around) {
        return;
    }
    try {
        engine_.limitWithdrawal(model::WithdrawLimit{*around, settings_.eraseWithdrawMm});
        withdrawLimited_ = true;
    } catch (const std::exception&) {
        // The erase stands; its run then takes back as much as the speed says, as before.
    }
}

void Workflow::liftWithdrawLimit() {
    if (!withdrawLimited_) {
        return;
    }
    withdrawLimited_ = false;
    try {
        engine_.limitWithdrawal(std::nullopt);
    } catch (const std::exception&) {
        // An engine that fails here fails the next step too, which says so.
    }
}

void Workflow::endReach() {
    eraseWatch_.reset();
    liftWithdrawLimit();
    if (!reach_) {
        return;
    }
    reach_.reset();
    try {
        engine_.setReach(std::nullopt);
    } catch (const std::exception&) {
        // An engine that fails here fails the next step too, which says so.
    }
}

void Workflow::watchEraseRun(const model::Sphere& brush, double volumeBeforeMl) {
    const UndoEntry* erase = undo_.undoTop();
    if (settings_.eraseRunGrowth <= 0.0 || !reachOf(brush) || erase == nullptr ||
        !erase->after.snapshot || !(volumeBeforeMl > 0.0)) {
        return;
    }
    eraseWatch_ = EraseRunWatch{brush, volumeBeforeMl * (1.0 + settings_.eraseRunGrowth),
                                *erase->after.snapshot};
}

// The volume read while evolving may lag the level set by a few steps: the run is taken back
// a little later than it passed the limit, which changes nothing it keeps.
bool Workflow::takeBackEraseRun() {
    if (!eraseWatch_ || !(status_.volumeMl > eraseWatch_->limitMl)) {
        return false;
    }
    const EraseRunWatch watch = *eraseWatch_;
    eraseWatch_.reset();
    engine_.restore(watch.start);
    reachAround(watch.brush, true);
    refreshEngineStatus();
    erasesCreep_ = true;
    ++status_.eraseRunsTakenBack;
    status_.message =
        "the erase's run grew the surface by more than " +
        std::to_string(static_cast<int>(std::lround(settings_.eraseRunGrowth * 100.0))) +
        " %: back to the erase, and away from it the surface only withdraws";
    return true;
}

Workflow::Outcome Workflow::first(const model::Correct& a) {
    if (!a.positive) {
        return no("nothing to correct yet: the first correction adds (a positive click)");
    }
    if (std::string problem = sphereProblem(a.voxel, a.radius); !problem.empty()) {
        return no(std::move(problem));
    }
    const ProbeResult p = engine_.probe(a.voxel, settings_.probeRadiusMm);
    if (p.count == 0 || !std::isfinite(p.mean) || !std::isfinite(p.stddev)) {
        return no("the scan's values under the click are not finite numbers");
    }
    lastProbe_ = p;
    const model::Sphere sphere = brushSphere(a.voxel, a.radius);
    // One undo step: the probe's T and eps and both inside examples come with the seed.
    ParamValues next = params_;
    holdInBox(next, sphere);
    takeProbe(next, p);
    if (auto example = exampleAt(a.voxel, settings_.probeRadiusMm)) {
        addExample(next.speed.inside, *example);
    }
    addExample(next.speed.inside, sphere);
    // The first sphere holds too: a positive click is never worth less than its paint, and
    // the deepest part of what the operator pointed at is where the threshold may be wrong.
    std::string notice;
    editLevelSet(
        "correct", [&] { notice = stickyEdit(sphere, true); }, status_.seeds + 1, status_.erasures,
        &next);
    if (!notice.empty()) {
        status_.message = notice;
    }
    return ok();
}

} // namespace steerseg::workflow
