#include "mask_stats.hpp"

#include <algorithm>
#include <cmath>
#include <itkImageRegionConstIteratorWithIndex.h>
#include <itkSignedMaurerDistanceMapImageFilter.h>
#include <stdexcept>

namespace steerseg::itkbench {

MaskStats maskStats(const FloatImage* scan, const MaskImage* mask) {
    if (const std::string why = gridMismatch(scan, mask); !why.empty()) {
        throw std::runtime_error("scan and mask are on different grids: " + why);
    }
    MaskStats s;
    double sum = 0.0;
    double sumSq = 0.0;
    itk::ImageRegionConstIteratorWithIndex<MaskImage> it(mask, mask->GetLargestPossibleRegion());
    for (it.GoToBegin(); !it.IsAtEnd(); ++it) {
        if (it.Get() == 0) {
            continue;
        }
        const auto idx = it.GetIndex();
        const double v = static_cast<double>(scan->GetPixel(idx));
        ++s.voxels;
        sum += v;
        sumSq += v * v;
        for (unsigned d = 0; d < 3; ++d) {
            s.centroid[d] += static_cast<double>(idx[d]);
        }
    }
    if (s.voxels == 0) {
        throw std::runtime_error("the mask is empty");
    }
    const double n = static_cast<double>(s.voxels);
    s.mean = sum / n;
    s.std = std::sqrt(std::max(0.0, sumSq / n - s.mean * s.mean));
    MaskImage::IndexType nearest;
    for (unsigned d = 0; d < 3; ++d) {
        s.centroid[d] /= n;
        nearest[d] = static_cast<itk::IndexValueType>(std::lround(s.centroid[d]));
    }
    s.centroidInside = mask->GetPixel(nearest) != 0;

    // Distances in voxels (unit spacing), like the seed radius and the PDE's units.
    using DistanceFilter = itk::SignedMaurerDistanceMapImageFilter<MaskImage, FloatImage>;
    auto distance = DistanceFilter::New();
    distance->SetInput(mask);
    distance->SetUseImageSpacing(false);
    distance->SetInsideIsPositive(true);
    distance->SetSquaredDistance(false);
    distance->SetBackgroundValue(0);
    try {
        distance->Update();
    } catch (const itk::ExceptionObject& e) {
        throw std::runtime_error(std::string("distance map: ") + e.GetDescription());
    }
    const FloatImage* dist = distance->GetOutput();
    s.depth = -1.0;
    for (it.GoToBegin(); !it.IsAtEnd(); ++it) {
        if (it.Get() == 0) {
            continue;
        }
        const double d = static_cast<double>(dist->GetPixel(it.GetIndex()));
        if (d > s.depth) {
            s.depth = d;
            for (unsigned a = 0; a < 3; ++a) {
                s.deepest[a] = it.GetIndex()[a];
            }
        }
    }
    const double probeRadius = std::max(1.0, s.depth / 2.0);
    const auto reach = static_cast<itk::IndexValueType>(std::ceil(probeRadius));
    double probeSum = 0.0;
    double probeSumSq = 0.0;
    const auto size = mask->GetLargestPossibleRegion().GetSize();
    MaskImage::IndexType p;
    for (p[2] = s.deepest[2] - reach; p[2] <= s.deepest[2] + reach; ++p[2]) {
        for (p[1] = s.deepest[1] - reach; p[1] <= s.deepest[1] + reach; ++p[1]) {
            for (p[0] = s.deepest[0] - reach; p[0] <= s.deepest[0] + reach; ++p[0]) {
                double r2 = 0.0;
                bool inGrid = true;
                for (unsigned a = 0; a < 3; ++a) {
                    const double x = static_cast<double>(p[a] - s.deepest[a]);
                    r2 += x * x;
                    inGrid =
                        inGrid && p[a] >= 0 && p[a] < static_cast<itk::IndexValueType>(size[a]);
                }
                if (!inGrid || r2 > probeRadius * probeRadius || mask->GetPixel(p) == 0) {
                    continue;
                }
                const double v = static_cast<double>(scan->GetPixel(p));
                ++s.probeVoxels;
                probeSum += v;
                probeSumSq += v * v;
            }
        }
    }
    const double pn = static_cast<double>(s.probeVoxels);
    s.probeMean = probeSum / pn;
    s.probeStd = std::sqrt(std::max(0.0, probeSumSq / pn - s.probeMean * s.probeMean));
    s.seed = Seed{static_cast<double>(s.deepest[0]), static_cast<double>(s.deepest[1]),
                  static_cast<double>(s.deepest[2]), std::clamp(s.depth / 2.0, 1.0, 3.0)};
    return s;
}

} // namespace steerseg::itkbench
