#pragma once

// The receiving side: a Storage SCP (DCMTK's dcmnet) that takes images from the scanner or the
// PACS into an incoming store, one file per instance at <store>/<study UID>/<series UID>/<SOP
// instance UID>.dcm, each written through files::writeFileAtomically so that a listing never
// sees half a file. It answers C-ECHO, accepts only the configured calling AE titles (and, where
// given, their addresses), and refuses an association's objects past its byte quota. Several
// associations are served at once, each on a thread of its own (AssociationPool), so a slow or
// stalled sender does not hold up the others.
#include "net/tls_context.hpp"

#include <atomic>
#include <cstdint>
#include <filesystem>
#include <functional>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

namespace steerseg::net {

struct AllowedCaller {
    std::string aet;
    std::string host; // "" = from any address; else the caller's IP address as text
};

struct ScpSettings {
    std::string aet = "STEERSEG";
    int port = 11112;
    std::filesystem::path store;
    std::vector<AllowedCaller> allowed; // empty = nobody
    // Set: the port speaks TLS only. A caller must show a certificate that a trusted CA signed
    // before its association request is read at all; the AE title and address rules follow.
    std::optional<TlsSettings> tls;
    // Bytes one association may bring. An object is received in memory before its durable
    // write, so this also bounds the memory one association can take; past it the association
    // is aborted mid-object.
    std::uint64_t associationQuotaBytes = std::uint64_t{1} << 30;
    // A C-STORE is refused (0xA700, out of resources) when the store's file system would keep
    // less than this free after the write.
    std::uint64_t minFreeBytes = std::uint64_t{256} << 20;
    int timeoutSeconds = 30; // ACSE and DIMSE: a silent peer is dropped after this
    // From a connection to its whole A-ASSOCIATE-RQ: a connection that sends nothing (or half a
    // request) is closed after this, and never holds up the next caller meanwhile.
    int negotiationSeconds = 5;
    // Associations served at once; one more is rejected at once as busy (A-ASSOCIATE-RJ,
    // transient, local limit exceeded), so the sender can retry.
    int maxAssociations = 4;
    // Received series older than this are removed when the SCP opens and hourly after
    // (pruneStore); 0 keeps them.
    int keepDays = 0;
};

class ScpError : public std::runtime_error {
  public:
    using std::runtime_error::runtime_error;
};

// One line per event (stored, refused, rejected, echo, aborted), for the log or the terminal.
using ScpReport = std::function<void(const std::string& line)>;

class StorageScp {
  public:
    StorageScp(ScpSettings settings, ScpReport report);
    ~StorageScp();
    StorageScp(const StorageScp&) = delete;
    StorageScp& operator=(const StorageScp&) = delete;

    // Creates the store, prunes it and binds the port (throws ScpError naming it when it cannot).
    void open();
    // Serves associations, up to `maxAssociations` at once, until `stop` becomes true (checked at
    // least once a second); then waits for those still open to end (at most the DIMSE timeout).
    void serve(const std::atomic<bool>& stop);

  private:
    class Impl;
    std::unique_ptr<Impl> impl_;
};

// A UID as it may name a folder or file of the store: 1..64 digits and dots (PS3.5 9.1), so a
// peer's value can never reach outside the store.
bool isSafeUid(const std::string& uid);

} // namespace steerseg::net
