#include "itk_image_io.hpp"

#include <algorithm>
#include <cmath>
#include <itkImageFileReader.h>
#include <itkImageFileWriter.h>
#include <itkImageRegionConstIterator.h>
#include <itkImageRegionIterator.h>
#include <itkNiftiImageIO.h>
#include <itkNrrdImageIO.h>
#include <sstream>
#include <stdexcept>

namespace steerseg::itkbench {
namespace {

// Far beyond any scan this benchmark reads (a 1024^3 volume), small enough that a corrupt
// header cannot make ITK allocate tens of gigabytes.
constexpr double kMaxVoxels = 1024.0 * 1024.0 * 1024.0;

bool endsWith(const std::string& s, const std::string& suffix) {
    return s.size() >= suffix.size() &&
           s.compare(s.size() - suffix.size(), suffix.size(), suffix) == 0;
}

// The IO is chosen explicitly: ITK's IO factories are registered only through ITK_USE_FILE,
// which would also put ITK's headers on every include path of this folder without SYSTEM.
itk::ImageIOBase::Pointer imageIoFor(const std::string& path) {
    if (endsWith(path, ".nii") || endsWith(path, ".nii.gz")) {
        return itk::NiftiImageIO::New().GetPointer();
    }
    if (endsWith(path, ".nrrd") || endsWith(path, ".nhdr")) {
        return itk::NrrdImageIO::New().GetPointer();
    }
    throw std::runtime_error(path + ": unsupported extension (expected .nii, .nii.gz or .nrrd)");
}

template <typename TImage> typename TImage::Pointer readImage(const std::string& path) {
    auto reader = itk::ImageFileReader<TImage>::New();
    reader->SetFileName(path);
    reader->SetImageIO(imageIoFor(path));
    try {
        reader->UpdateOutputInformation();
        const auto size = reader->GetOutput()->GetLargestPossibleRegion().GetSize();
        const double voxels = static_cast<double>(size[0]) * static_cast<double>(size[1]) *
                              static_cast<double>(size[2]);
        if (voxels <= 0.0 || voxels > kMaxVoxels) {
            throw std::runtime_error(path + ": implausible grid size");
        }
        reader->Update();
    } catch (const itk::ExceptionObject& e) {
        throw std::runtime_error(path + ": " + e.GetDescription());
    }
    return reader->GetOutput();
}

} // namespace

FloatImage::Pointer readFloatImage(const std::string& path) {
    FloatImage::Pointer image = readImage<FloatImage>(path);
    itk::ImageRegionConstIterator<FloatImage> it(image, image->GetLargestPossibleRegion());
    for (it.GoToBegin(); !it.IsAtEnd(); ++it) {
        if (!std::isfinite(it.Get())) {
            throw std::runtime_error(path + ": contains NaN or infinite intensities");
        }
    }
    return image;
}

MaskImage::Pointer readMask(const std::string& path) {
    MaskImage::Pointer mask = readImage<MaskImage>(path);
    itk::ImageRegionIterator<MaskImage> it(mask, mask->GetLargestPossibleRegion());
    for (it.GoToBegin(); !it.IsAtEnd(); ++it) {
        it.Set(it.Get() != 0 ? 1 : 0);
    }
    return mask;
}

void writeMask(const std::string& path, const MaskImage* mask) {
    auto writer = itk::ImageFileWriter<MaskImage>::New();
    writer->SetFileName(path);
    writer->SetImageIO(imageIoFor(path));
    writer->SetInput(mask);
    writer->SetUseCompression(true);
    try {
        writer->Update();
    } catch (const itk::ExceptionObject& e) {
        throw std::runtime_error(path + ": " + e.GetDescription());
    }
}

std::string gridMismatch(const itk::ImageBase<3>* a, const itk::ImageBase<3>* b) {
    auto close = [](double x, double y) {
        return std::abs(x - y) <= 1e-4 * std::max({1.0, std::abs(x), std::abs(y)});
    };
    std::ostringstream why;
    const auto sa = a->GetLargestPossibleRegion().GetSize();
    const auto sb = b->GetLargestPossibleRegion().GetSize();
    if (sa != sb) {
        why << "dims " << sa << " vs " << sb;
        return why.str();
    }
    for (unsigned d = 0; d < 3; ++d) {
        if (!close(a->GetSpacing()[d], b->GetSpacing()[d])) {
            why << "spacing " << a->GetSpacing() << " vs " << b->GetSpacing();
            return why.str();
        }
        if (!close(a->GetOrigin()[d], b->GetOrigin()[d])) {
            why << "origin " << a->GetOrigin() << " vs " << b->GetOrigin();
            return why.str();
        }
        for (unsigned e = 0; e < 3; ++e) {
            if (!close(a->GetDirection()[d][e], b->GetDirection()[d][e])) {
                why << "direction differs";
                return why.str();
            }
        }
    }
    return {};
}

} // namespace steerseg::itkbench
