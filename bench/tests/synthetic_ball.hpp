#pragma once

#include "itk_image_io.hpp"

#include <algorithm>
#include <cmath>
#include <itkImageRegionIteratorWithIndex.h>

namespace steerseg::itkbench::test {

// A 32^3 float scan: `inside` within `radius` voxels (index units) of voxel (16, 16, 16),
// `outside` elsewhere, with a linear ramp `edge` voxels wide centred on the radius (0: a sharp
// step); spacing 2 x 1 x 1 so that a solver using the spacing would show it. A step edge never
// lets ITK's RMS criterion converge: the front hops back and forth between two voxels.
inline FloatImage::Pointer syntheticBall(double radius, float inside, float outside,
                                         double edge = 0.0) {
    auto image = FloatImage::New();
    FloatImage::SizeType size;
    size.Fill(32);
    image->SetRegions(FloatImage::RegionType(size));
    FloatImage::SpacingType spacing;
    spacing[0] = 2.0;
    spacing[1] = 1.0;
    spacing[2] = 1.0;
    image->SetSpacing(spacing);
    image->Allocate();
    itk::ImageRegionIteratorWithIndex<FloatImage> it(image, image->GetLargestPossibleRegion());
    for (it.GoToBegin(); !it.IsAtEnd(); ++it) {
        double d2 = 0.0;
        for (unsigned d = 0; d < 3; ++d) {
            const double x = static_cast<double>(it.GetIndex()[d]) - 16.0;
            d2 += x * x;
        }
        const double r = std::sqrt(d2);
        const double w = edge > 0.0 ? std::clamp((r - radius) / edge + 0.5, 0.0, 1.0)
                                    : (r <= radius ? 0.0 : 1.0);
        it.Set(static_cast<float>((1.0 - w) * static_cast<double>(inside) +
                                  w * static_cast<double>(outside)));
    }
    return image;
}

// The ball itself as a mask on the same grid.
inline MaskImage::Pointer thresholdMask(const FloatImage* image, float above) {
    auto mask = MaskImage::New();
    mask->CopyInformation(image);
    mask->SetRegions(image->GetLargestPossibleRegion());
    mask->Allocate();
    itk::ImageRegionIteratorWithIndex<MaskImage> it(mask, mask->GetLargestPossibleRegion());
    for (it.GoToBegin(); !it.IsAtEnd(); ++it) {
        it.Set(image->GetPixel(it.GetIndex()) > above ? 1 : 0);
    }
    return mask;
}

} // namespace steerseg::itkbench::test
