#pragma once

// The segmentation options shared by `segment` and `render` (which segments before drawing):
// one parser, one validation, one way to run the solver.
#include "cli/args.hpp"
#include "core/volume.hpp"
#include "solver/level_set_solver.hpp"

#include <string>
#include <vector>

namespace steerseg::cli {

// What to run: exactly one of --iterations, --time, --converge.
struct RunMode {
    enum Kind { Iterations, Time, Converge } kind = Iterations;
    int iterations = 0; // the count, or the cap for --time / --converge
    float time = 0.0F;
};

struct SegmentationRequest {
    LevelSetParams params;
    std::vector<Sphere> seeds;
    std::vector<Sphere> erases;
    RunMode mode;
    SolverOptions options;
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

struct SegmentationRun {
    StepResult result;
    double solveSeconds = 0.0; // solver only, GPU work finished
};

// Applies seeds, erasers and parameters to a fresh solver and runs it as the request says.
SegmentationRun runSegmentation(LevelSetSolver& solver, const SegmentationRequest& request);

} // namespace steerseg::cli
