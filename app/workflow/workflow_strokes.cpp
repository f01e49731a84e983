// Painted strokes (model::PaintStroke): the brush along a drag's path, one undo step for the
// whole stroke. Add and erase are level-set edits like a seed's and an eraser's (snapshots before
// and after, workflow_edits.cpp); outside is a change of classify's examples like an outside
// mark's. The dabs of add and outside strokes all train classify (SpeedChoice::painted*).
#include "workflow/stroke_dabs.hpp"
#include "workflow/workflow.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <string>
#include <vector>

namespace steerseg::workflow {

namespace {

// Spheres per stroke: a scribble across a 512-voxel slice and back at the smallest brush. The
// engine edits the level set once per sphere, so this bounds how long one stroke takes.
constexpr std::size_t kMaxStrokeDabs = 8192;

std::string where(const glm::dvec3& p) {
    std::ostringstream s;
    s << "(" << p.x << ", " << p.y << ", " << p.z << ")";
    return s.str();
}

} // namespace

Workflow::Outcome Workflow::on(const model::PaintStroke& a) {
    if (a.points.empty()) {
        return no("a stroke needs at least one point");
    }
    if (a.points.size() > model::kMaxStrokePoints) {
        return no("a stroke of " + std::to_string(a.points.size()) + " points: at most " +
                  std::to_string(model::kMaxStrokePoints) + " in one stroke");
    }
    if (!std::isfinite(a.radius)) {
        return no("a stroke needs a finite radius");
    }
    const glm::ivec3 dims = status_.scan.dims;
    for (std::size_t p = 0; p < a.points.size(); ++p) {
        const glm::dvec3& v = a.points[p];
        if (!std::isfinite(v.x) || !std::isfinite(v.y) || !std::isfinite(v.z)) {
            return no("stroke point " + std::to_string(p + 1) + " is not a finite position");
        }
        for (int i = 0; i < 3; ++i) {
            if (v[i] < 0.0 || v[i] > static_cast<double>(dims[i] - 1)) {
                std::ostringstream msg;
                msg << "stroke point " << p + 1 << " " << where(v) << " lies outside the scan ("
                    << dims.x << " x " << dims.y << " x " << dims.z << " voxels)";
                return no(msg.str());
            }
        }
    }
    if (a.mode == model::StrokeMode::Erase && !status_.hasLevelSet) {
        return no("nothing to erase");
    }
    const ParamRange& range = status_.ranges[indexOf(model::Param::Radius)];
    const double radius =
        a.radius > 0.0 ? clampTo(range, a.radius) : params_.values[indexOf(model::Param::Radius)];
    // Half the radius apart: the tube the spheres paint is nearly as wide between two of them as
    // at their centres.
    const double spacing = std::max(0.5 * radius, 0.5);
    const std::optional<std::vector<glm::dvec3>> centres = strokeDabs(
        a.points, spacing, kMaxStrokeDabs, glm::dvec3(model::sphereScale(status_.scan.spacing)));
    if (!centres) {
        std::ostringstream msg;
        msg << "the stroke is too long for a brush of radius " << radius << " (more than "
            << kMaxStrokeDabs << " spheres): lift the finger sooner or widen the brush";
        return no(msg.str());
    }
    std::vector<model::Sphere> dabs;
    dabs.reserve(centres->size());
    for (const glm::dvec3& c : *centres) {
        dabs.push_back({glm::vec3(c), static_cast<float>(radius)});
    }
    ParamValues next = params_;
    switch (a.mode) {
    case model::StrokeMode::Add:
        addPainted(next.speed.paintedInside, dabs);
        for (const model::Sphere& s : dabs) {
            holdInBox(next, s);
        }
        editLevelSet(
            "paint_stroke",
            [&] {
                for (const model::Sphere& s : dabs) {
                    engine_.addSeed(s);
                }
            },
            status_.seeds + 1, status_.erasures, &next);
        if (status_.state == model::State::Inspect) {
            enter(model::State::Seeding); // as the first seed does
        }
        return ok();
    case model::StrokeMode::Erase:
        editLevelSet(
            "paint_stroke",
            [&] {
                for (const model::Sphere& s : dabs) {
                    engine_.erase(s);
                }
            },
            status_.seeds, status_.erasures + 1);
        if (status_.state == model::State::Evolving && !status_.hasLevelSet) {
            enter(model::State::Paused, "the level set is empty: add a seed");
        }
        return ok();
    case model::StrokeMode::Outside:
        addPainted(next.speed.paintedOutside, dabs);
        return changeParams(std::move(next), "paint_stroke", std::nullopt);
    }
    return no("unknown stroke mode");
}

} // namespace steerseg::workflow
