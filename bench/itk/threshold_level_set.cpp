#include "threshold_level_set.hpp"

#include "cli/args.hpp"
#include "timed_threshold_filter.hpp"

#include <chrono>
#include <cmath>
#include <ctime>
#include <itkImageRegionConstIterator.h>
#include <itkImageRegionIterator.h>
#include <itkMultiThreaderBase.h>
#include <stdexcept>

namespace steerseg::itkbench {
namespace {

// Time-limited runs still need an iteration cap: where the speed vanishes on the whole front,
// ITK's time step is 0 and the time limit would never be reached.
constexpr long long kDefaultIterationCap = 1'000'000;

void checkParams(const LevelSetParams& p) {
    if (!std::isfinite(p.target)) {
        throw cli::UsageError("--T must be finite");
    }
    if (!(p.epsilon > 0.0) || !std::isfinite(p.epsilon)) {
        throw cli::UsageError("--eps must be > 0");
    }
    if (!(p.alpha >= 0.0 && p.alpha <= 1.0)) {
        throw cli::UsageError("--alpha must be in [0, 1]");
    }
    if (p.stop == StopRule::Iterations && p.iterations < 1) {
        throw cli::UsageError("--iterations must be >= 1");
    }
    if (p.stop == StopRule::Time && !(p.time > 0.0 && std::isfinite(p.time))) {
        throw cli::UsageError("--time must be > 0");
    }
    if (p.stop == StopRule::Converge && (p.iterations < 1 || !(p.maxRmsChange > 0.0))) {
        throw cli::UsageError("--converge needs --max-iterations >= 1 and --rms > 0");
    }
}

MaskImage::Pointer insideMask(const FloatImage* phi, long long& insideVoxels) {
    auto mask = MaskImage::New();
    mask->CopyInformation(phi);
    mask->SetRegions(phi->GetLargestPossibleRegion());
    mask->Allocate();
    itk::ImageRegionConstIterator<FloatImage> in(phi, phi->GetLargestPossibleRegion());
    itk::ImageRegionIterator<MaskImage> out(mask, mask->GetLargestPossibleRegion());
    insideVoxels = 0;
    for (in.GoToBegin(), out.GoToBegin(); !in.IsAtEnd(); ++in, ++out) {
        const bool inside = in.Get() < 0.0F;
        out.Set(inside ? 1 : 0);
        insideVoxels += inside ? 1 : 0;
    }
    return mask;
}

} // namespace

LevelSetResult runThresholdLevelSet(const FloatImage* scan, std::span<const Seed> seeds,
                                    const LevelSetParams& params) {
    checkParams(params);
    const FloatImage::Pointer initial = seedLevelSet(scan, seeds, params.spheres);

    auto filter = TimedThresholdLevelSetFilter::New();
    filter->SetInput(initial);
    filter->SetFeatureImage(scan);
    filter->SetLowerThreshold(static_cast<float>(params.target - params.epsilon));
    filter->SetUpperThreshold(static_cast<float>(params.target + params.epsilon));
    filter->SetEdgeWeight(0.0F);
    filter->SetPropagationScaling(static_cast<float>(params.alpha));
    filter->SetCurvatureScaling(static_cast<float>(1.0 - params.alpha));
    filter->SetAdvectionScaling(0.0F);
    filter->SetUseImageSpacing(false);
    filter->SetInterpolateSurfaceLocation(params.interpolateSurface);
    filter->SetIsoSurfaceValue(0.0F);
    switch (params.stop) {
    case StopRule::Iterations:
        filter->SetNumberOfIterations(static_cast<itk::IdentifierType>(params.iterations));
        filter->SetMaximumRMSError(0.0);
        break;
    case StopRule::Time:
        filter->SetNumberOfIterations(static_cast<itk::IdentifierType>(
            params.iterations > 0 ? params.iterations : kDefaultIterationCap));
        filter->SetMaximumRMSError(0.0);
        filter->SetTimeLimit(params.time);
        break;
    case StopRule::Converge:
        filter->SetNumberOfIterations(static_cast<itk::IdentifierType>(params.iterations));
        filter->SetMaximumRMSError(params.maxRmsChange);
        break;
    }

    LevelSetResult result;
    const std::clock_t cpu0 = std::clock();
    const auto wall0 = std::chrono::steady_clock::now();
    try {
        filter->Update();
    } catch (const itk::ExceptionObject& e) {
        throw std::runtime_error(std::string("ITK level set: ") + e.GetDescription());
    }
    const auto wall1 = std::chrono::steady_clock::now();
    const std::clock_t cpu1 = std::clock();
    result.solveSeconds = std::chrono::duration<double>(wall1 - wall0).count();
    result.cpuSeconds = static_cast<double>(cpu1 - cpu0) / static_cast<double>(CLOCKS_PER_SEC);
    result.iterations = static_cast<long long>(filter->GetElapsedIterations());
    result.evolvedTime = filter->GetEvolvedTime();
    result.rmsChange = filter->GetRMSChange();
    result.converged =
        params.stop == StopRule::Converge && filter->GetRMSChange() < params.maxRmsChange;
    result.threads = itk::MultiThreaderBase::GetGlobalDefaultNumberOfThreads();
    result.mask = insideMask(filter->GetOutput(), result.insideVoxels);
    return result;
}

} // namespace steerseg::itkbench
