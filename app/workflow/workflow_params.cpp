// The speed's parameters and the brush: probe, presets, absolute and relative changes, the
// knob's selection. Every change is clamped to the scan's ranges, sent to the engine at once
// (live while evolving) and recorded for undo.
#include "workflow/one_line.hpp"
#include "workflow/workflow.hpp"

#include <algorithm>
#include <cmath>
#include <utility>

namespace steerseg::workflow {

namespace {

bool validParam(model::Param p) {
    return indexOf(p) < static_cast<std::size_t>(model::kParamCount);
}

bool speedParam(model::Param p) {
    return p != model::Param::Radius;
}

} // namespace

ParamValues Workflow::clamped(ParamValues v) const {
    for (std::size_t i = 0; i < v.values.size(); ++i) {
        const ParamRange& r = status_.ranges[i];
        // T, eps and alpha travel to the solver as floats: keep the float the status shows.
        v.values[i] = i == indexOf(model::Param::Radius)
                          ? clampTo(r, v.values[i])
                          : static_cast<double>(clampToFloat(r, v.values[i]));
    }
    return v;
}

void Workflow::applyParams(const ParamValues& values, bool force) {
    // The speed first: when the engine refuses it (it throws) nothing has changed yet.
    SpeedChoice want = speedFor(values);
    const bool newSpeed = force || want != engineSpeed_;
    if (newSpeed) {
        if (want.kind != engineSpeed_.kind) {
            erasesCreep_ = false; // another speed may tell the structure from its surroundings
        }
        endReach(); // the operator's new speed applies everywhere
        engine_.setSpeed(want);
        engineSpeed_ = std::move(want);
        status_.converged = false;
    }
    showSpeed(values, engineSpeed_.kind);
    const model::LevelSetParams p{static_cast<float>(values.values[indexOf(model::Param::T)]),
                                  static_cast<float>(values.values[indexOf(model::Param::Eps)]),
                                  static_cast<float>(values.values[indexOf(model::Param::Alpha)])};
    const model::LevelSetParams& now = status_.params;
    if (force || p.T != now.T || p.eps != now.eps || p.alpha != now.alpha) {
        erasesCreep_ = false;
        endReach();
        engine_.setParams(p);
        status_.converged = false; // the front moves again under a new speed
    }
    params_ = values;
    status_.params = p;
    status_.radius = values.values[indexOf(model::Param::Radius)];
    status_.preset = values.preset;
}

ParamValues Workflow::defaultParams() const {
    // A probe or a preset is the operator's real first step; until then a centred, wide band
    // and some smoothing, as the sample's demo uses.
    const double lo = status_.scan.minValue;
    const double hi = status_.scan.maxValue;
    ParamValues v;
    v.values[indexOf(model::Param::T)] = lo + (hi - lo) / 2.0;
    v.values[indexOf(model::Param::Eps)] = std::max(settings_.epsFloor, (hi - lo) / 10.0);
    v.values[indexOf(model::Param::Alpha)] = 0.8;
    v.values[indexOf(model::Param::Radius)] = settings_.defaultRadius;
    v.speed.kind = settings_.defaultSpeed;
    return clamped(v);
}

void Workflow::setDefaultParams() {
    ParamValues v = defaultParams();
    try {
        applyParams(clamped(v), true); // a new scan: the engine hears its parameters
    } catch (const std::exception& e) {
        if (settings_.defaultSpeed == model::SpeedKind::Threshold) {
            throw;
        }
        // The scan is fine; the operator can still steer with the paper's speed.
        v.speed.kind = model::SpeedKind::Threshold;
        applyParams(clamped(v), true);
        status_.message = "the threshold speed runs: " + oneLine(e.what());
    }
}

Workflow::Outcome Workflow::changeParams(ParamValues next, std::string_view what,
                                         std::optional<model::Param> coalesce) {
    UndoEntry e;
    e.what = what;
    e.paramsBefore = params_;
    applyParams(clamped(std::move(next)));
    e.paramsAfter = params_;
    e.coalesce = coalesce;
    undo_.push(std::move(e));
    return ok();
}

Workflow::Outcome Workflow::setParam(model::Param param, double value, std::string_view what) {
    if (!validParam(param)) {
        return no("unknown parameter");
    }
    if (!std::isfinite(value)) {
        return no(std::string(model::paramName(param)) + " must be a finite number");
    }
    ParamValues next = params_;
    next.values[indexOf(param)] = value;
    if (speedParam(param)) {
        next.preset.clear(); // the speed no longer is the preset's
    }
    return changeParams(std::move(next), what, param);
}

Workflow::Outcome Workflow::on(const model::SetParam& a) {
    return setParam(a.param, a.value, "set_param");
}

Workflow::Outcome Workflow::on(const model::NudgeParam& a) {
    if (!validParam(a.param)) {
        return no("unknown parameter");
    }
    if (!std::isfinite(a.steps)) {
        return no("a nudge needs a finite number of steps");
    }
    const std::size_t i = indexOf(a.param);
    const ParamRange& r = status_.ranges[i];
    const double delta = a.steps * r.fineStep;
    double v = params_.values[i] + delta;
    if (!std::isfinite(v)) { // a flood of steps overflowed: as far as the range goes
        v = delta > 0.0 ? r.max : r.min;
    }
    return setParam(a.param, v, "nudge_param");
}

Workflow::Outcome Workflow::on(const model::NudgeSelected& a) {
    if (const std::optional<model::Box> box = knobBox(a.steps)) {
        // At the scan's border or the opposite face the face stays, and so does undo's stack.
        return *box == status_.box ? ok() : on(model::SetBox{*box});
    }
    return on(model::NudgeParam{status_.selected, a.steps});
}

Workflow::Outcome Workflow::on(const model::SelectParam& a) {
    if (!validParam(a.param)) {
        return no("unknown parameter");
    }
    status_.selected = a.param;
    status_.boxFace.reset(); // the knob drives the parameter, not the box's face
    return ok();
}

Workflow::Outcome Workflow::on(const model::CycleParam& a) {
    const long long n = model::kParamCount;
    const long long next = ((static_cast<long long>(status_.selected) + a.delta) % n + n) % n;
    status_.selected = static_cast<model::Param>(next);
    status_.boxFace.reset();
    return ok();
}

Workflow::Outcome Workflow::on(const model::Probe& a) {
    if (!std::isfinite(a.voxel.x) || !std::isfinite(a.voxel.y) || !std::isfinite(a.voxel.z) ||
        !std::isfinite(a.radiusMm)) {
        return no("a probe needs a finite position and radius");
    }
    const double radius = a.radiusMm > 0.0 ? a.radiusMm : settings_.probeRadiusMm;
    const ProbeResult p = engine_.probe(a.voxel, radius);
    if (p.count == 0) {
        return no("probe outside the scan");
    }
    if (!std::isfinite(p.mean) || !std::isfinite(p.stddev)) {
        return no("the scan's values under the probe are not finite numbers");
    }
    lastProbe_ = p;
    ParamValues next = params_;
    // The probe's sphere is the classifier's inside example (the tissue the operator wants).
    if (auto example = exampleAt(a.voxel, radius)) {
        addExample(next.speed.inside, *example);
    }
    takeProbe(next, p);
    return changeParams(std::move(next), "probe", std::nullopt);
}

void Workflow::takeProbe(ParamValues& values, const ProbeResult& p) const {
    values.values[indexOf(model::Param::T)] = p.mean;
    values.values[indexOf(model::Param::Eps)] =
        std::max(settings_.probeEpsFactor * p.stddev, settings_.epsFloor);
    values.preset.clear();
}

Workflow::Outcome Workflow::on(const model::ApplyPreset& a) {
    const auto it = std::find_if(settings_.presets.begin(), settings_.presets.end(),
                                 [&](const TissuePreset& p) { return p.name == a.name; });
    if (it == settings_.presets.end()) {
        return no("unknown preset '" + a.name + "'");
    }
    ParamValues next = params_;
    next.values[indexOf(model::Param::T)] = it->T;
    next.values[indexOf(model::Param::Eps)] = it->eps;
    next.values[indexOf(model::Param::Alpha)] = it->alpha;
    next.preset = it->name;
    Outcome out = changeParams(std::move(next), "apply_preset", std::nullopt);
    if (it->windowWidth > 0.0) {
        status_.view.windowLevel = it->windowLevel;
        status_.view.windowWidth = it->windowWidth;
    }
    if (!it->transfer.empty()) {
        status_.view.transfer = it->transfer;
    }
    return out;
}

} // namespace steerseg::workflow
