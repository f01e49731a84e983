// ITK's DICOM series read, the reference for steerseg's DICOM reader in large_scan_bench: the
// code of ITK's own example (DicomSeriesReadImageWrite2: GDCMSeriesFileNames ->
// ImageSeriesReader with GDCMImageIO, default settings) into an int16 image, which holds the
// rescaled HU of a CT as steerseg keeps them (int16 stored, rescale applied on use).
//   steerseg-itk-dicom-read DIR
// Prints one JSON line: wall seconds of the read (the folder's scan included, as steerseg's
// reader does it), peak resident bytes above the process's size at the start of main (VmHWM -
// VmRSS, so ITK's libraries do not count), the size, and the sum of the voxels in HU (to check
// that both readers read the same numbers). Run it in its own process: the peak is the read's.
#include "bench/proc_status.hpp"

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <itkGDCMImageIO.h>
#include <itkGDCMSeriesFileNames.h>
#include <itkImage.h>
#include <itkImageRegionConstIterator.h>
#include <itkImageSeriesReader.h>
#include <string>

int main(int argc, char** argv) {
    if (argc != 2) {
        std::fprintf(stderr, "usage: steerseg-itk-dicom-read DIR\n");
        return 2;
    }
    using Image = itk::Image<short, 3>;
    try {
        const double before = steerseg::bench::statusBytes("VmRSS");
        const auto start = std::chrono::steady_clock::now();
        auto names = itk::GDCMSeriesFileNames::New();
        names->SetUseSeriesDetails(true);
        names->SetDirectory(argv[1]);
        const auto& series = names->GetSeriesUIDs();
        if (series.empty()) {
            std::fprintf(stderr, "steerseg-itk-dicom-read: %s: no DICOM series\n", argv[1]);
            return 1;
        }
        auto reader = itk::ImageSeriesReader<Image>::New();
        reader->SetImageIO(itk::GDCMImageIO::New());
        reader->SetFileNames(names->GetFileNames(series.front()));
        reader->Update();
        const double seconds =
            std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        const double peak = steerseg::bench::statusBytes("VmHWM") - before;
        const Image* image = reader->GetOutput();
        const auto size = image->GetLargestPossibleRegion().GetSize();
        double sum = 0.0;
        for (itk::ImageRegionConstIterator<Image> it(image, image->GetLargestPossibleRegion());
             !it.IsAtEnd(); ++it) {
            sum += it.Get();
        }
        std::printf("{\"seconds\": %.4f, \"peak_bytes\": %.0f, \"dims\": [%lu, %lu, %lu], "
                    "\"series\": %zu, \"sum\": %.1f}\n",
                    seconds, peak, static_cast<unsigned long>(size[0]),
                    static_cast<unsigned long>(size[1]), static_cast<unsigned long>(size[2]),
                    series.size(), sum);
        return 0;
    } catch (const std::exception& e) {
        std::fprintf(stderr, "steerseg-itk-dicom-read: %s\n", e.what());
        return 1;
    }
}
