#pragma once

// Decodes one DICOM file's pixel data through GDCM (every transfer syntax GDCM supports) and
// copies its frames into slices of a Volume.
#include "scan/dicom/header.hpp"

#include <memory>
#include <span>

namespace steerseg::scan {

// The attributes a rescale comes from, for messages.
inline constexpr const char* kDicomRescaleFields =
    "Rescale Slope (0028,1053)/Rescale Intercept (0028,1052)";

// How decoded frames are stored: in their native type with one shared rescale, or as float32
// real values when rescales differ between frames or the data is 32-bit.
struct PixelPlan {
    VoxelType type = VoxelType::Float32;
    bool realUnits = true; // float32 holding rescaled values; the volume's rescale is identity
    Rescale shared;        // the volume's rescale when !realUnits
};

// The plan for frames with these headers (all frames of all files of one series).
PixelPlan planPixels(std::span<const DicomHeader> files);

// Thrown by DicomPixels::copyFrames when a decoded value does not fit the plan's native type
// (GDCM decoded another pixel format than the header announced): the caller retries with a
// float32 plan.
struct PixelPlanMismatch {};

class DicomPixels {
  public:
    // Reads and decodes the whole file. Throws ScanError naming the file and the problem.
    explicit DicomPixels(const DicomHeader& header);
    ~DicomPixels();
    DicomPixels(const DicomPixels&) = delete;
    DicomPixels& operator=(const DicomPixels&) = delete;

    // Copies frame f into slice sliceOfFrame[f] of `out` (whose dims match the frames), applying
    // planes[f].rescale if plan.realUnits. MONOCHROME1 values are inverted (see docs/dicom.md).
    void copyFrames(std::span<const std::size_t> sliceOfFrame,
                    std::span<const DicomFramePlane> planes, const PixelPlan& plan,
                    Volume& out) const;

  private:
    struct Decoded;
    std::unique_ptr<Decoded> d_;
};

} // namespace steerseg::scan
