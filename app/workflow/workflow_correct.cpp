// The operator's correction (model::Correct): the clicks protocol's unit (docs/steering.md). The
// first one, on a scan without a level set, does what an operator's first taps do: probe
// there (T and eps from the tissue), seed there; a later one is the seed or the erase of a tap
// in add or remove mode while steering (workflow_edits.cpp: an erase then sticks).
#include "workflow/workflow.hpp"

#include <cmath>

namespace steerseg::workflow {

Workflow::Outcome Workflow::on(const model::Correct& a) {
    // The table then runs the solver from the surface this leaves.
    return status_.hasLevelSet ? sphereEdit(a.voxel, a.radius, a.positive) : first(a);
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
    takeProbe(next, p);
    if (auto example = exampleAt(a.voxel, settings_.probeRadiusMm)) {
        addExample(next.speed.inside, *example);
    }
    addExample(next.speed.inside, sphere);
    editLevelSet(
        "correct", [&] { engine_.addSeed(sphere); }, status_.seeds + 1, status_.erasures, &next);
    return ok();
}

} // namespace steerseg::workflow
