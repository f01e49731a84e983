#pragma once

// Internal to net: how a received object becomes a file of the incoming store, whoever brought
// it (a Storage SCP association, a C-GET's C-STORE), and what the node accepts to receive. One
// file per instance at <store>/<study UID>/<series UID>/<SOP instance UID>.dcm, written through
// files::writeFileAtomically, after the checks that keep a peer's values inside the store and
// the disk above its free-space floor.
#include "net/store_scp.hpp"

#include <atomic>
#include <cstdint>
#include <filesystem>
#include <memory>
#include <mutex>
#include <span>
#include <string>

class DcmDataset;

namespace steerseg::net {

// What the writers filing at once share: the report, one line at a time, and the disk space
// the objects being written will take, so that two writers cannot both pass the free-space
// check on the same free bytes.
class StoreShared {
  public:
    explicit StoreShared(ScpReport report) : report_(std::move(report)) {}
    void report(const std::string& line);
    // Reserves `bytes` when the store keeps `minFree` free after them and the other writers'
    // reservations; otherwise false, with what is free for the others in `available`.
    bool reserve(const std::filesystem::path& store, std::uint64_t bytes, std::uint64_t minFree,
                 std::uint64_t& available);
    void release(std::uint64_t bytes);
    // The SCP's stop, so that an association cut off by it says so (none for a C-GET).
    const std::atomic<bool>* stop = nullptr;
    [[nodiscard]] bool stopping() const { return stop != nullptr && *stop; }

  private:
    std::mutex reportMutex_;
    ScpReport report_;
    std::mutex spaceMutex_;
    std::uint64_t reserved_ = 0;
};

// The image storage SOP classes the node takes (DCMTK's dcmImageSOPClassUIDs) and the transfer
// syntaxes GDCM (scan/) reads, uncompressed first: the node's preference.
std::span<const char* const> acceptedImageSopClasses();
std::span<const char* const> acceptedTransferSyntaxes();

class SeriesMarks;

// Where one object goes and who brought it, for the checks and the report's lines.
struct FilingTarget {
    std::filesystem::path store;
    std::uint64_t minFreeBytes = 0;
    std::string from; // " from AE", appended to the report's lines
    // Set: the series is marked as being received (series_marks) before the object lands.
    SeriesMarks* marks = nullptr;
};

// Files `dataset` (taken) as received in `transferSyntaxUid` for a C-STORE request of
// `requestSopClass` / `requestSopInstance`: the DIMSE status to answer (PS3.4 B.2.3: 0x0000
// stored, 0xA900 the data set's SOP class or instance differs from the request's, 0xC000 no
// usable UIDs or not encodable, 0xA700 below the free-space floor or the write failed), each
// outcome reported in one line ("stored <study>/<series>/<sop>.dcm from AE (N bytes)",
// "refused object from AE: why").
std::uint16_t fileObject(std::unique_ptr<DcmDataset> dataset, const std::string& requestSopClass,
                         const std::string& requestSopInstance,
                         const std::string& transferSyntaxUid, const FilingTarget& target,
                         StoreShared& shared);

} // namespace steerseg::net
