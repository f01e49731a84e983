#pragma once

#include "itk_image_io.hpp"
#include "seed_level_set.hpp"

#include <span>

namespace steerseg::itkbench {

enum class StopRule { Iterations, Time, Converge };

// The PDE and stopping rule, in steerseg's terms: speed alpha*(eps - |I - T|) + (1 - alpha)*H.
struct LevelSetParams {
    double target = 0.0;  // T
    double epsilon = 0.0; // eps > 0
    double alpha = 0.5;   // in [0, 1]
    StopRule stop = StopRule::Converge;
    long long iterations = 0;        // Iterations: exactly this many; Converge: the cap
    double time = 0.0;               // Time: evolve until the summed time step reaches this
    double maxRmsChange = 0.02;      // Converge: ITK's MaximumRMSError
    bool interpolateSurface = false; // ITK's InterpolateSurfaceLocation (speed at the zero set)
    SeedSpheres spheres = SeedSpheres::Millimetres; // what the seeds' radii measure
};

struct LevelSetResult {
    MaskImage::Pointer mask; // inside (phi < 0) = 1, on the scan's grid
    long long iterations = 0;
    double evolvedTime = 0.0;
    double solveSeconds = 0.0; // wall time of the filter's Update() only
    double cpuSeconds = 0.0;   // process CPU time over the same span (threads at work)
    bool converged = false;    // stopped by the RMS criterion before the cap
    double rmsChange = 0.0;    // last iteration's RMS change of the active layer
    long long insideVoxels = 0;
    unsigned threads = 0; // ITK's global default thread count
};

// Runs itk::ThresholdSegmentationLevelSetImageFilter on `scan` from the seed spheres with
// lower = T - eps, upper = T + eps, PropagationScaling = alpha, CurvatureScaling = 1 - alpha,
// no advection, no edge term, UseImageSpacing off (derivatives and time in voxel units).
// Throws std::runtime_error (ITK failures included) and cli::UsageError for bad parameters.
LevelSetResult runThresholdLevelSet(const FloatImage* scan, std::span<const Seed> seeds,
                                    const LevelSetParams& params);

} // namespace steerseg::itkbench
