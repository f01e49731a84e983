// The Storage SCP's filing, shared with the C-GET of retrieve_scu so that a retrieved series is
// in the store exactly as a pushed one.
#include "net/store_filing.hpp"

#include "exports/dicom_file_bytes.hpp"
#include "files/file_write.hpp"
#include "net/series_marks.hpp"

#include <dcmtk/config/osconfig.h> // must come first among DCMTK's headers
#include <dcmtk/dcmdata/dcdeftag.h>
#include <dcmtk/dcmdata/dcfilefo.h>
#include <dcmtk/dcmdata/dcuid.h>
#include <dcmtk/dcmdata/dcxfer.h>
#include <system_error>
#include <vector>

namespace steerseg::net {
namespace {

const char* const kTransferSyntaxes[] = {
    UID_LittleEndianExplicitTransferSyntax, UID_LittleEndianImplicitTransferSyntax,
    UID_BigEndianExplicitTransferSyntax,    UID_DeflatedExplicitVRLittleEndianTransferSyntax,
    UID_JPEGProcess1TransferSyntax,         UID_JPEGProcess2_4TransferSyntax,
    UID_JPEGProcess14TransferSyntax,        UID_JPEGProcess14SV1TransferSyntax,
    UID_JPEGLSLosslessTransferSyntax,       UID_JPEGLSLossyTransferSyntax,
    UID_JPEG2000LosslessOnlyTransferSyntax, UID_JPEG2000TransferSyntax,
    UID_RLELosslessTransferSyntax,
};

// PS3.4 B.2.3 status codes.
constexpr std::uint16_t kSuccess = 0x0000;
constexpr std::uint16_t kOutOfResources = 0xA700;
constexpr std::uint16_t kCannotUnderstand = 0xC000;
constexpr std::uint16_t kDataSetMismatch = 0xA900;

std::string text(DcmDataset& dataset, const DcmTagKey& tag) {
    OFString value;
    dataset.findAndGetOFString(tag, value);
    return value.c_str();
}

// Another writer may write into the same series at the same moment: the folders' creation
// tolerates that, and each file has its own temporary name until its rename.
std::uint16_t write(const FilingTarget& target, const std::string& study, const std::string& series,
                    const std::string& sop, const std::vector<std::byte>& bytes,
                    StoreShared& shared) {
    const std::filesystem::path folder = target.store / study / series;
    std::error_code ec;
    std::filesystem::create_directories(folder, ec);
    if (target.marks != nullptr) {
        if (const std::string why = target.marks->mark(folder); !why.empty()) {
            shared.report("refused object" + target.from + ": " + why);
            return kOutOfResources;
        }
    }
    try {
        files::writeFileAtomically(folder / (sop + ".dcm"), {std::span<const std::byte>(bytes)});
    } catch (const std::exception& e) {
        shared.report("refused object" + target.from + ": " + e.what());
        return kOutOfResources;
    }
    shared.report("stored " + (std::filesystem::path(study) / series / (sop + ".dcm")).string() +
                  target.from + " (" + std::to_string(bytes.size()) + " bytes)");
    return kSuccess;
}

} // namespace

void StoreShared::report(const std::string& line) {
    const std::lock_guard lock(reportMutex_);
    report_(line);
}

bool StoreShared::reserve(const std::filesystem::path& store, std::uint64_t bytes,
                          std::uint64_t minFree, std::uint64_t& available) {
    const std::lock_guard lock(spaceMutex_);
    std::error_code ec;
    const auto space = std::filesystem::space(store, ec);
    if (ec) {
        // Cannot tell: the write itself says whether the disk holds it.
        reserved_ += bytes;
        return true;
    }
    available = space.available > reserved_ ? space.available - reserved_ : 0;
    if (available < bytes + minFree) {
        return false;
    }
    reserved_ += bytes;
    return true;
}

void StoreShared::release(std::uint64_t bytes) {
    const std::lock_guard lock(spaceMutex_);
    reserved_ -= bytes;
}

std::span<const char* const> acceptedImageSopClasses() {
    return {dcmImageSOPClassUIDs, static_cast<std::size_t>(numberOfDcmImageSOPClassUIDs)};
}

std::span<const char* const> acceptedTransferSyntaxes() {
    return kTransferSyntaxes;
}

std::uint16_t fileObject(std::unique_ptr<DcmDataset> dataset, const std::string& requestSopClass,
                         const std::string& requestSopInstance,
                         const std::string& transferSyntaxUid, const FilingTarget& target,
                         StoreShared& shared) {
    const std::string study = text(*dataset, DCM_StudyInstanceUID);
    const std::string series = text(*dataset, DCM_SeriesInstanceUID);
    const std::string sop = text(*dataset, DCM_SOPInstanceUID);
    if (sop != requestSopInstance || text(*dataset, DCM_SOPClassUID) != requestSopClass) {
        shared.report("refused object" + target.from +
                      ": its SOP class or instance differs from the request's");
        return kDataSetMismatch;
    }
    if (!isSafeUid(study) || !isSafeUid(series) || !isSafeUid(sop)) {
        shared.report("refused object" + target.from +
                      ": Study, Series or SOP Instance UID missing or not a UID");
        return kCannotUnderstand;
    }
    OFCondition c;
    DcmFileFormat fileFormat(dataset.release(), OFFalse);
    const E_TransferSyntax xfer = DcmXfer(transferSyntaxUid.c_str()).getXfer();
    // In 1 MiB passes: the object is in memory once already, its encoding once more.
    const std::vector<std::byte> bytes =
        exports::dicomFileBytes(fileFormat, xfer, std::size_t{1} << 20, c);
    if (c.bad()) {
        shared.report("refused object" + target.from + ": cannot be encoded: " + c.text());
        return kCannotUnderstand;
    }
    // Before any folder is made: a refused object leaves no empty series behind.
    std::uint64_t available = 0;
    if (!shared.reserve(target.store, bytes.size(), target.minFreeBytes, available)) {
        shared.report("refused object" + target.from + ": the store has " +
                      std::to_string(available >> 20) + " MiB free, less than the object and " +
                      std::to_string(target.minFreeBytes >> 20) + " MiB to keep");
        return kOutOfResources;
    }
    const std::uint16_t status = write(target, study, series, sop, bytes, shared);
    shared.release(bytes.size());
    return status;
}

} // namespace steerseg::net
