#include "scan/dicom/header.hpp"

#include "scan/byte_source.hpp"
#include "scan/dicom/multiframe.hpp"
#include "scan/dicom/structure.hpp"
#include "scan/load_checks.hpp"

#include <charconv>
#include <cmath>
#include <fstream>
#include <gdcmReader.h>
#include <gdcmStringFilter.h>
#include <gdcmTrace.h>

namespace steerseg::scan {

namespace {

const gdcm::Tag kPixelData(0x7fe0, 0x0010);

std::string trim(std::string_view s) {
    const auto pad = [](char c) {
        return c == ' ' || c == '\0' || c == '\t' || c == '\r' || c == '\n';
    };
    while (!s.empty() && pad(s.front())) {
        s.remove_prefix(1);
    }
    while (!s.empty() && pad(s.back())) {
        s.remove_suffix(1);
    }
    return std::string(s);
}

std::optional<double> parseDecimal(std::string_view s) {
    std::string t = trim(s);
    std::string_view v = t;
    if (!v.empty() && v.front() == '+') {
        v.remove_prefix(1);
    }
    double value = 0.0;
    const auto [end, ec] = std::from_chars(v.data(), v.data() + v.size(), value);
    if (v.empty() || ec != std::errc() || end != v.data() + v.size() || !std::isfinite(value)) {
        return std::nullopt;
    }
    return value;
}

// Integer attributes of binary VR (US) depend on the transfer syntax's byte order and, for
// implicit VR, on the dictionary: StringFilter handles both.
int readInteger(const gdcm::StringFilter& sf, const gdcm::DataSet& ds, const gdcm::Tag& tag,
                int fallback) {
    if (!ds.FindDataElement(tag) || ds.GetDataElement(tag).IsEmpty()) {
        return fallback;
    }
    const std::string text = trim(sf.ToString(tag));
    int value = 0;
    const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
    if (text.empty() || ec != std::errc()) {
        return fallback;
    }
    (void)end; // multi-valued text ("16\\16") keeps its first value
    return value;
}

std::optional<double> readOneDecimal(const std::filesystem::path& path, const gdcm::DataSet& ds,
                                     const gdcm::Tag& tag, const char* what) {
    const auto v = readDecimals(path, ds, tag, 1, what);
    if (v.empty()) {
        return std::nullopt;
    }
    return v[0];
}

// What a derived object (DICOM SEG) copies from its source: Specific Character Set, and the
// Patient, General Study, Patient Study and Frame of Reference modules' text attributes.
constexpr std::pair<std::uint16_t, std::uint16_t> kInheritedTags[] = {
    {0x0008, 0x0005}, // SpecificCharacterSet
    {0x0010, 0x0010}, // PatientName
    {0x0010, 0x0020}, // PatientID
    {0x0010, 0x0021}, // IssuerOfPatientID
    {0x0010, 0x0030}, // PatientBirthDate
    {0x0010, 0x0032}, // PatientBirthTime
    {0x0010, 0x0040}, // PatientSex
    {0x0010, 0x2160}, // EthnicGroup
    {0x0010, 0x4000}, // PatientComments
    {0x0012, 0x0062}, // PatientIdentityRemoved
    {0x0012, 0x0063}, // DeidentificationMethod
    {0x0020, 0x000d}, // StudyInstanceUID
    {0x0008, 0x0020}, // StudyDate
    {0x0008, 0x0030}, // StudyTime
    {0x0008, 0x0090}, // ReferringPhysicianName
    {0x0020, 0x0010}, // StudyID
    {0x0008, 0x0050}, // AccessionNumber
    {0x0008, 0x1030}, // StudyDescription
    {0x0010, 0x1010}, // PatientAge
    {0x0010, 0x1020}, // PatientSize
    {0x0010, 0x1030}, // PatientWeight
    {0x0020, 0x0052}, // FrameOfReferenceUID
    {0x0020, 0x1040}, // PositionReferenceIndicator
};

} // namespace

void openForGdcm(gdcm::Reader& reader, const std::filesystem::path& file, std::uintmax_t dataSetEnd,
                 std::uintmax_t fileSize, std::unique_ptr<std::istringstream>& holder) {
    if (dataSetEnd >= fileSize) {
        reader.SetFileName(file.string().c_str());
        return;
    }
    std::string head(static_cast<std::size_t>(dataSetEnd), '\0');
    std::ifstream in(file, std::ios::binary);
    if (!in.read(head.data(), static_cast<std::streamsize>(head.size()))) {
        throw ScanError(file, "cannot read the file");
    }
    holder = std::make_unique<std::istringstream>(std::move(head));
    reader.SetStream(*holder);
}

void quietGdcm() {
    gdcm::Trace::SetDebug(false);
    gdcm::Trace::SetWarning(false);
    gdcm::Trace::SetError(false);
}

bool mightBeDicom(const std::filesystem::path& path) {
    std::ifstream in(path, std::ios::binary);
    unsigned char head[132] = {};
    in.read(reinterpret_cast<char*>(head), sizeof head);
    const auto got = in.gcount();
    if (got == static_cast<std::streamsize>(sizeof head) && head[128] == 'D' && head[129] == 'I' &&
        head[130] == 'C' && head[131] == 'M') {
        return true;
    }
    // A data set without preamble starts with the little-endian group number of its first tag.
    return got >= 8 && head[1] == 0x00 && (head[0] == 0x02 || head[0] == 0x08);
}

std::string readText(const gdcm::DataSet& ds, const gdcm::Tag& tag) {
    if (!ds.FindDataElement(tag)) {
        return {};
    }
    const gdcm::ByteValue* bv = ds.GetDataElement(tag).GetByteValue();
    if (bv == nullptr || bv->GetPointer() == nullptr) {
        return {};
    }
    return trim(std::string_view(bv->GetPointer(), bv->GetLength()));
}

std::vector<double> readDecimals(const std::filesystem::path& path, const gdcm::DataSet& ds,
                                 const gdcm::Tag& tag, std::size_t count, const char* what) {
    const std::string text = readText(ds, tag);
    if (text.empty()) {
        return {};
    }
    std::vector<double> values;
    std::size_t start = 0;
    while (start <= text.size()) {
        const std::size_t stop = std::min(text.find('\\', start), text.size());
        const auto value = parseDecimal(std::string_view(text).substr(start, stop - start));
        if (!value || values.size() == count) {
            throw ScanError(path, std::string(what) + " is \"" + text + "\", not " +
                                      std::to_string(count) + " finite number" +
                                      (count > 1 ? "s" : ""));
        }
        values.push_back(*value);
        start = stop + 1;
    }
    if (values.size() != count) {
        throw ScanError(path, std::string(what) + " is \"" + text + "\", not " +
                                  std::to_string(count) + " numbers");
    }
    return values;
}

DicomHeader readDicomHeader(const std::filesystem::path& path, const ReadLimits& limits) {
    const std::uint64_t dataSetEnd = checkDicomStructure(path);
    std::error_code sizeEc;
    const std::uintmax_t fileSize = std::filesystem::file_size(path, sizeEc);
    gdcm::Reader reader;
    std::unique_ptr<std::istringstream> holder;
    openForGdcm(reader, path, dataSetEnd, fileSize, holder);
    // Skip the pixel data's value: scanning a folder should not read every image twice.
    if (!reader.ReadUpToTag(kPixelData, {kPixelData})) {
        throw ScanError(path, "not a readable DICOM file (damaged, truncated or not DICOM)");
    }
    const gdcm::File& file = reader.GetFile();
    const gdcm::DataSet& ds = file.GetDataSet();
    gdcm::StringFilter sf;
    sf.SetFile(file);

    DicomHeader h;
    h.file = path;
    h.fileSize = fileSize;
    h.dataSetEnd = dataSetEnd;
    h.sopClassUid = readText(ds, gdcm::Tag(0x0008, 0x0016));
    h.mediaStorageSopClassUid = readText(file.GetHeader(), gdcm::Tag(0x0002, 0x0002));
    h.sopInstanceUid = readText(ds, gdcm::Tag(0x0008, 0x0018));
    h.mediaStorageSopInstanceUid = readText(file.GetHeader(), gdcm::Tag(0x0002, 0x0003));
    h.studyUid = readText(ds, gdcm::Tag(0x0020, 0x000d));
    h.frameOfReferenceUid = readText(ds, gdcm::Tag(0x0020, 0x0052));
    h.lossyCompression = readText(ds, gdcm::Tag(0x0028, 0x2110));
    h.lossyRatio = readText(ds, gdcm::Tag(0x0028, 0x2112));
    h.lossyMethod = readText(ds, gdcm::Tag(0x0028, 0x2114));
    for (const auto& [group, element] : kInheritedTags) {
        if (ds.FindDataElement(gdcm::Tag(group, element))) {
            h.inherited.push_back({group, element, readText(ds, gdcm::Tag(group, element))});
        }
    }
    h.modality = readText(ds, gdcm::Tag(0x0008, 0x0060));
    h.seriesUid = readText(ds, gdcm::Tag(0x0020, 0x000e));
    h.description = readText(ds, gdcm::Tag(0x0008, 0x103e));
    h.rows = readInteger(sf, ds, gdcm::Tag(0x0028, 0x0010), 0);
    h.columns = readInteger(sf, ds, gdcm::Tag(0x0028, 0x0011), 0);
    h.samplesPerPixel = readInteger(sf, ds, gdcm::Tag(0x0028, 0x0002), 1);
    h.bitsAllocated = readInteger(sf, ds, gdcm::Tag(0x0028, 0x0100), 0);
    h.bitsStored = readInteger(sf, ds, gdcm::Tag(0x0028, 0x0101), h.bitsAllocated);
    h.highBit = readInteger(sf, ds, gdcm::Tag(0x0028, 0x0102), h.bitsStored - 1);
    h.isSigned = readInteger(sf, ds, gdcm::Tag(0x0028, 0x0103), 0) == 1;
    h.photometric = readText(ds, gdcm::Tag(0x0028, 0x0004));
    const std::string frames = readText(ds, gdcm::Tag(0x0028, 0x0008));
    if (!frames.empty()) {
        const auto n = parseDecimal(frames);
        if (!n || *n < 1.0 || *n > 1e9 || std::floor(*n) != *n) {
            throw ScanError(path, "NumberOfFrames is \"" + frames + "\", not a positive integer");
        }
        h.frames = static_cast<int>(*n);
    }
    const gdcm::TransferSyntax ts = file.GetHeader().GetDataSetTransferSyntax();
    h.rawPixelData =
        !ts.IsEncapsulated() && ts != gdcm::TransferSyntax::DeflatedExplicitVRLittleEndian;
    const std::string increment = trim(sf.ToString(gdcm::Tag(0x0028, 0x0009)));
    h.framesAreTimePoints = increment == "(0018,1063)" || increment == "(0018,1065)";

    const auto iop =
        readDecimals(path, ds, gdcm::Tag(0x0020, 0x0037), 6, "ImageOrientationPatient");
    if (!iop.empty()) {
        h.orientation = {{iop[0], iop[1], iop[2]}, {iop[3], iop[4], iop[5]}};
    }
    auto ps = readDecimals(path, ds, gdcm::Tag(0x0028, 0x0030), 2, "PixelSpacing");
    if (ps.empty()) {
        ps = readDecimals(path, ds, gdcm::Tag(0x0018, 0x1164), 2, "ImagerPixelSpacing");
    }
    if (!ps.empty()) {
        h.pixelSpacing = glm::dvec2(ps[1], ps[0]);
    }
    h.sliceThickness = readOneDecimal(path, ds, gdcm::Tag(0x0018, 0x0050), "SliceThickness");
    h.spacingBetweenSlices =
        readOneDecimal(path, ds, gdcm::Tag(0x0018, 0x0088), "SpacingBetweenSlices");

    DicomFramePlane plane;
    const auto ipp = readDecimals(path, ds, gdcm::Tag(0x0020, 0x0032), 3, "ImagePositionPatient");
    if (!ipp.empty()) {
        plane.position = glm::dvec3(ipp[0], ipp[1], ipp[2]);
    }
    plane.rescale.slope =
        readOneDecimal(path, ds, gdcm::Tag(0x0028, 0x1053), "RescaleSlope").value_or(1.0);
    plane.rescale.intercept =
        readOneDecimal(path, ds, gdcm::Tag(0x0028, 0x1052), "RescaleIntercept").value_or(0.0);
    if (h.isImage()) {
        checkDims(path, {h.columns, h.rows, h.frames}, limits);
        const std::uint64_t bits = static_cast<std::uint64_t>(h.columns) *
                                   static_cast<std::uint64_t>(h.rows) *
                                   static_cast<std::uint64_t>(h.frames) *
                                   static_cast<std::uint64_t>(std::max(h.samplesPerPixel, 1)) *
                                   static_cast<std::uint64_t>(std::max(h.bitsAllocated, 0));
        // Compressed pixel data (JPEG, RLE, ...) is decoded by GDCM into a buffer of the declared
        // size, so the declaration is bounded before GDCM sees it.
        checkDataLimit(path, (bits + 7) / 8, limits,
                       "the image declares " + dimsText({h.columns, h.rows, h.frames}) + " x " +
                           std::to_string(h.bitsAllocated) + " bits (" + sizeText((bits + 7) / 8) +
                           ")");
        const std::size_t offset = reader.GetStreamCurrentPosition();
        if (h.rawPixelData && offset != static_cast<std::size_t>(-1) && offset <= h.fileSize) {
            checkAvailable(path, (bits + 7) / 8, h.fileSize - offset, "the pixel data");
        }
        h.planes.assign(static_cast<std::size_t>(h.frames), plane);
        readFunctionalGroups(path, ds, h);
    }
    for (const auto& p : h.planes) {
        if (p.rescale.slope == 0.0) {
            throw ScanError(path, "RescaleSlope is 0, so every voxel would have the same value");
        }
    }
    return h;
}

} // namespace steerseg::scan
