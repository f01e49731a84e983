#pragma once

// One association of the Storage SCP, on its own thread: negotiation against the configured
// callers, C-ECHO, and each C-STORE filed through the durable write path, within the
// association's byte quota and the store's free-space floor.
#include "net/store_scp.hpp"

#include <cstdint>
#include <filesystem>
#include <mutex>
#include <string>

struct T_ASC_Association;

namespace steerseg::net {

// What the associations served at once share: the report, one line at a time, and the disk
// space the objects being written will take, so that two writers cannot both pass the
// free-space check on the same free bytes.
class StoreShared {
  public:
    explicit StoreShared(ScpReport report) : report_(std::move(report)) {}
    void report(const std::string& line);
    // Reserves `bytes` when the store keeps `minFree` free after them and the other writers'
    // reservations; otherwise false, with what is free for the others in `available`.
    bool reserve(const std::filesystem::path& store, std::uint64_t bytes, std::uint64_t minFree,
                 std::uint64_t& available);
    void release(std::uint64_t bytes);

  private:
    std::mutex reportMutex_;
    ScpReport report_;
    std::mutex spaceMutex_;
    std::uint64_t reserved_ = 0;
};

// Serves `assoc` to its end, then drops and destroys it.
void serveStoreAssociation(T_ASC_Association* assoc, const ScpSettings& settings,
                           StoreShared& shared);

} // namespace steerseg::net
