// The speed function and the classifier's examples: the operator's choice of data term, the
// outside marks (the probes and the seeds are the inside examples, workflow_params.cpp and
// workflow_edits.cpp) and the outside mode.
// A change travels through changeParams like a parameter's: sent to the engine (which may
// refuse it) and recorded for undo.
#include "model/speed_kind.hpp"
#include "workflow/probe_sphere.hpp"
#include "workflow/workflow.hpp"

#include <algorithm>
#include <cmath>
#include <span>
#include <utility>

namespace steerseg::workflow {

const SpeedOff* Workflow::speedOff(model::SpeedKind kind) const {
    for (const SpeedOff& off : settings_.speedsOff) {
        if (off.kind == kind) {
            return &off;
        }
    }
    return nullptr;
}

SpeedChoice Workflow::speedFor(const ParamValues& values) const {
    const SpeedChoice& chosen = values.speed;
    SpeedChoice out;
    out.box = chosen.box; // whatever runs stays in the box
    // A resumed session or an old undo entry may name a speed this GPU computes wrong.
    if (speedOff(chosen.kind) != nullptr) {
        out.kind = settings_.defaultSpeed;
        return out;
    }
    if (chosen.kind == model::SpeedKind::Classify) {
        if (chosen.hasInside() && chosen.hasOutside()) {
            out = chosen;
            out.withinWindow = settings_.classifyWithinWindow;
            out.placeReach = settings_.classifyPlaceReach;
            return out;
        }
        out.kind = speedOff(values.fallback) != nullptr ? settings_.defaultSpeed : values.fallback;
        return out;
    }
    out.kind = chosen.kind;
    return out;
}

std::optional<model::Sphere> Workflow::exampleAt(const glm::dvec3& voxel, double radiusMm) const {
    const glm::ivec3 dims = status_.scan.dims;
    for (int a = 0; a < 3; ++a) {
        if (!(voxel[a] >= 0.0 && voxel[a] <= static_cast<double>(dims[a] - 1))) {
            return std::nullopt;
        }
    }
    // At least the voxel under the finger.
    return probeSphere(voxel, radiusMm, status_.scan.spacing, dims, 0.5);
}

namespace {

// Appends `add`, then drops the oldest past `most`.
void appendNewest(std::vector<model::Sphere>& list, std::span<const model::Sphere> add,
                  std::size_t most) {
    list.insert(list.end(), add.begin(), add.end());
    if (list.size() > most) {
        list.erase(list.begin(), list.begin() + static_cast<std::ptrdiff_t>(list.size() - most));
    }
}

} // namespace

void Workflow::addExample(std::vector<model::Sphere>& examples, const model::Sphere& example) {
    appendNewest(examples, {&example, 1}, model::kMaxExamples);
}

void Workflow::addPainted(std::vector<model::Sphere>& painted,
                          const std::vector<model::Sphere>& spheres) {
    appendNewest(painted, spheres, kMaxPaintedExamples);
}

void Workflow::showSpeed(const ParamValues& values, model::SpeedKind inForce) {
    status_.speed = values.speed.kind;
    status_.speedInForce = inForce;
    status_.insideExamples = values.speed.inside;
    status_.outsideExamples = values.speed.outside;
    status_.paintedInside = values.speed.paintedInside;
    status_.paintedOutside = values.speed.paintedOutside;
    status_.box = values.speed.box;
}

Workflow::Outcome Workflow::on(const model::SetSpeed& a) {
    if (!model::validSpeedKind(a.kind)) {
        return no("unknown speed");
    }
    if (speedOff(a.kind) != nullptr) {
        // The why stands in the alarm above the message (Status::gpuAlarm).
        return no("the " + std::string(model::speedKindName(a.kind)) +
                  " speed is off: this GPU computed it wrong at start-up");
    }
    if (a.kind == params_.speed.kind) {
        return ok();
    }
    ParamValues next = params_;
    if (a.kind == model::SpeedKind::Classify) {
        next.fallback = engineSpeed_.kind; // what runs until the classifier has its examples
    }
    next.speed.kind = a.kind;
    Outcome out = changeParams(std::move(next), "set_speed", std::nullopt);
    if (status_.speed == model::SpeedKind::Classify &&
        status_.speedInForce != model::SpeedKind::Classify) {
        status_.message = "classify needs an inside example (a probe or a seed) and an outside "
                          "example; the " +
                          std::string(model::speedKindName(status_.speedInForce)) +
                          " speed runs until then";
    }
    return out;
}

Workflow::Outcome Workflow::on(const model::MarkOutside& a) {
    if (!std::isfinite(a.voxel.x) || !std::isfinite(a.voxel.y) || !std::isfinite(a.voxel.z) ||
        !std::isfinite(a.radiusMm)) {
        return no("an outside example needs a finite position and radius");
    }
    const double radius = a.radiusMm > 0.0 ? a.radiusMm : settings_.probeRadiusMm;
    const std::optional<model::Sphere> example = exampleAt(a.voxel, radius);
    if (!example) {
        return no("outside example outside the scan");
    }
    ParamValues next = params_;
    addExample(next.speed.outside, *example);
    return changeParams(std::move(next), "mark_outside", std::nullopt);
}

Workflow::Outcome Workflow::on(const model::ClearExamples&) {
    ParamValues next = params_;
    next.speed.inside.clear();
    next.speed.outside.clear();
    next.speed.paintedInside.clear();
    next.speed.paintedOutside.clear();
    Outcome out = changeParams(std::move(next), "clear_examples", std::nullopt);
    if (status_.speed == model::SpeedKind::Classify) {
        status_.message = "examples cleared: the " +
                          std::string(model::speedKindName(status_.speedInForce)) +
                          " speed runs until classify has new ones";
    }
    return out;
}

Workflow::Outcome Workflow::on(const model::SetOutsideMode& a) {
    status_.outsideMode = a.outside;
    if (a.outside) {
        status_.eraseMode = false; // one meaning per tap
        status_.boxMode = false;
        status_.boxFace.reset();
    }
    return ok();
}

} // namespace steerseg::workflow
