#pragma once

// The segmentation options shared by `segment` and `render` (which segments before drawing):
// one parser, one validation, one way to run the solver.
#include "cli/args.hpp"
#include "core/volume.hpp"
#include "session/session.hpp"
#include "session/speed_settings.hpp"

#include <optional>
#include <string>
#include <vector>

namespace steerseg::cli {

struct SegmentationRequest {
    // T and eps are final once completeWithScan has applied --probe.
    model::LevelSetParams params;
    session::SpeedSettings speed; // --speed, --smooth, --conductance, --kappa, --inside, --outside
    std::optional<model::Sphere> probe;
    bool explicitT = false;
    bool explicitEps = false;
    bool explicitConductance = false;
    bool explicitKappa = false;
    std::vector<model::Sphere> seeds;
    std::vector<model::Sphere> erases;
    std::vector<model::Sphere> barriers;
    session::RunMode mode; // exactly one of --iterations, --time, --converge
    model::SolverOptions options;
};

// Option names to declare to Args.
std::vector<std::string> segmentationValueOptions();
std::vector<std::string> segmentationFlagOptions();

// True if any option that asks for a segmentation is present.
bool wantsSegmentation(const Args& args);

// Parses and validates everything that needs no scan; throws UsageError.
SegmentationRequest parseSegmentation(const Args& args);

// With the scan read: every sphere option must lie in the scan, --probe fills the parameters not
// given explicitly (session::probeSpeed) and the result is validated; throws UsageError naming
// the option.
void completeWithScan(SegmentationRequest& request, const Volume& scan);

// Applies the request's seeds, erasers, barriers, parameters and speed to the session.
void applySegmentation(session::Session& session, const SegmentationRequest& request);

} // namespace steerseg::cli
