// The operator's box (model::SetBox, docs/steering.md "The box"): the prompt the interactive
// challenge, ITK-SNAP's snake and nnInteractive start from. It bounds the surface (the speed
// blocks outside it: the engine's barrier), and on a scan without a level set it gives T and
// eps, the first probe and seed and classify's inside examples, from the tissue that fills it.
// What lies outside it is not taken as classify's outside: the shell of a tumour is the muscle
// it looks like, and a forest trained on it emptied the box (docs/steering-log.md). It is one
// of the parameters (SpeedChoice::box): undo, redo and autosave carry it as they carry T.
#include "workflow/box_tissue.hpp"
#include "workflow/probe_sphere.hpp"
#include "workflow/workflow.hpp"

#include <algorithm>
#include <cmath>
#include <exception>
#include <limits>

namespace steerseg::workflow {

namespace {

// The values a box's tissue is read from: a histogram's worth, whatever the box's size.
constexpr std::size_t kBoxSamples = 20000;
// Where the first seed may go: a 5 x 5 x 5 grid over the inner box.
constexpr int kSeedGrid = 5;

} // namespace

std::vector<glm::dvec3> Workflow::boxTissueAt(const model::Box& box, const TissuePeak& tissue,
                                              double probeMm) const {
    // Candidates on a grid over the inner box and its centre: those whose probe reads the
    // tissue, nearest the centre (mm) first; else the one that reads nearest to it.
    const model::Box inner = innerBox(box);
    const glm::dvec3 centre = model::centreOf(box);
    const glm::dvec3& spacing = status_.scan.spacing;
    std::vector<std::pair<double, glm::dvec3>> found;
    glm::dvec3 closest = centre;
    double closestOff = std::numeric_limits<double>::infinity();
    const auto consider = [&](const glm::dvec3& at) {
        const ProbeResult m = engine_.measure(at, probeMm);
        if (m.count == 0 || !std::isfinite(m.mean)) {
            return;
        }
        const double off = std::abs(m.mean - tissue.level);
        if (off < closestOff) {
            closestOff = off;
            closest = at;
        }
        if (off <= tissue.sigma) {
            found.emplace_back(glm::length((at - centre) * spacing), at);
        }
    };
    consider(centre);
    for (int c = 0; c < kSeedGrid; ++c) {
        for (int b = 0; b < kSeedGrid; ++b) {
            for (int a = 0; a < kSeedGrid; ++a) {
                const glm::dvec3 f = (glm::dvec3(a, b, c) + 0.5) / static_cast<double>(kSeedGrid);
                consider(
                    glm::round(glm::dvec3(inner.lo) + f * glm::dvec3(model::sizeOf(inner) - 1)));
            }
        }
    }
    std::stable_sort(found.begin(), found.end(),
                     [](const auto& x, const auto& y) { return x.first < y.first; });
    std::vector<glm::dvec3> out;
    for (const auto& f : found) {
        out.push_back(f.second);
    }
    if (out.empty()) {
        out.push_back(closest);
    }
    return out;
}

void Workflow::holdInBox(ParamValues& values, const model::Sphere& seed) const {
    if (values.speed.box) {
        values.speed.box = model::boxHolding(
            *values.speed.box, seed, model::sphereScale(status_.scan.spacing), status_.scan.dims);
    }
}

Workflow::Outcome Workflow::on(const model::SetBox& a) {
    try {
        model::validateBox(a.box, status_.scan.dims);
    } catch (const std::exception& e) {
        return no(e.what());
    }
    ParamValues next = params_;
    next.speed.box = a.box;
    if (status_.hasLevelSet) {
        // The surface follows: outside the new box it recedes, inside it may grow again (a new
        // speed for the engine, so a correction's reach ends with it).
        return changeParams(std::move(next), "set_box", std::nullopt);
    }
    // The first prompt: T and eps from the tissue that fills the box's inner part, the probe
    // and the seed where that tissue lies nearest the box's centre (workflow/box_tissue.hpp).
    const std::optional<TissuePeak> tissue =
        dominantTissue(engine_.values(innerBox(a.box), kBoxSamples));
    if (!tissue) {
        return no("the scan's values in the box are not finite numbers");
    }
    const glm::dvec3& spacing = status_.scan.spacing;
    const double finest = std::min({spacing.x, spacing.y, spacing.z});
    // The probe is no larger than a quarter of the box's smallest side.
    const glm::dvec3 sideMm = glm::dvec3(model::sizeOf(a.box)) * spacing;
    const double probeMm =
        std::max(std::min(0.25 * std::min({sideMm.x, sideMm.y, sideMm.z}), settings_.probeRadiusMm),
                 0.5 * finest);
    const std::vector<glm::dvec3> tissueAt = boxTissueAt(a.box, *tissue, probeMm);
    const glm::dvec3 centre = tissueAt.front();
    const ProbeResult p = engine_.probe(centre, probeMm); // the edge speed's noise region
    if (p.count == 0 || !std::isfinite(p.mean) || !std::isfinite(p.stddev)) {
        return no("the scan's values in the box are not finite numbers");
    }
    lastProbe_ = p;
    takeProbe(next, {tissue->level, tissue->sigma, p.count, 0});
    const model::Sphere example = probeSphere(centre, probeMm, spacing, status_.scan.dims, 0.5);
    addExample(next.speed.inside, example);
    // Every place the box's tissue was read is an inside example: the classifier learns the
    // structure from all of the box, not from one probe's sphere.
    std::vector<model::Sphere> more;
    for (std::size_t n = 1; n < tissueAt.size(); ++n) {
        more.push_back(probeSphere(tissueAt[n], probeMm, spacing, status_.scan.dims, 0.5));
    }
    addPainted(next.speed.paintedInside, more);
    // The seed is the brush, no larger than the probe: a seed wider than the structure would
    // start the surface outside it.
    const model::Sphere seed{example.centre,
                             std::min(example.radius, brushSphere(centre, 0.0).radius)};
    editLevelSet(
        "set_box", [&] { engine_.addSeed(seed); }, status_.seeds + 1, status_.erasures, &next);
    return ok();
}

Workflow::Outcome Workflow::on(const model::SetBoxMode& a) {
    if (a.face && (a.face->axis < 0 || a.face->axis > 2)) {
        return no("a box face's axis is 0, 1 or 2");
    }
    status_.boxMode = a.on;
    status_.boxFace = a.on ? a.face : std::nullopt;
    if (a.on) {
        status_.eraseMode = false; // one meaning per tap
        status_.outsideMode = false;
    }
    return ok();
}

std::optional<model::Box> Workflow::knobBox(double steps) const {
    // The knob moves the box while the surface follows it (seeding, evolving, paused); in
    // inspect a box would probe and seed, which a knob's detent must not.
    const model::State s = status_.state;
    if (!status_.boxMode || !status_.boxFace || !status_.box ||
        !(s == model::State::Seeding || s == model::State::Evolving || s == model::State::Paused) ||
        !std::isfinite(steps)) {
        return std::nullopt;
    }
    // A fraction of a detent (a touchpad's wheel) still moves a voxel in its direction.
    const double whole =
        steps > 0.0 ? std::max(std::round(steps), 1.0) : std::min(std::round(steps), -1.0);
    const auto voxels = static_cast<int>(std::clamp(whole, -1e6, 1e6));
    return model::movedFace(*status_.box, *status_.boxFace, voxels, status_.scan.dims);
}

Workflow::Outcome Workflow::on(const model::ClearBox&) {
    ParamValues next = params_;
    next.speed.box.reset();
    return changeParams(std::move(next), "clear_box", std::nullopt);
}

} // namespace steerseg::workflow
