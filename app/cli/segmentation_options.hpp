#pragma once

// The segmentation options shared by `segment` and `render` (which segments before drawing):
// one parser, one validation, one way to run the solver.
#include "cli/args.hpp"
#include "core/volume.hpp"
#include "session/session.hpp"

#include <string>
#include <vector>

namespace steerseg::cli {

struct SegmentationRequest {
    solver::LevelSetParams params;
    std::vector<solver::Sphere> seeds;
    std::vector<solver::Sphere> erases;
    std::vector<solver::Sphere> barriers;
    session::RunMode mode; // exactly one of --iterations, --time, --converge
    solver::SolverOptions options;
};

// Option names to declare to Args.
std::vector<std::string> segmentationValueOptions();
std::vector<std::string> segmentationFlagOptions();

// True if any option that asks for a segmentation is present.
bool wantsSegmentation(const Args& args);

// Parses and validates everything that needs no scan; throws UsageError.
SegmentationRequest parseSegmentation(const Args& args);

// Seeds and erasers must lie in the scan; throws UsageError naming the option.
void checkSpheresInside(const SegmentationRequest& request, const glm::ivec3& dims);

// Applies the request's seeds, erasers, barriers and parameters to the session.
void applySegmentation(session::Session& session, const SegmentationRequest& request);

} // namespace steerseg::cli
