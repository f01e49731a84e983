// The Storage SCP: the listening port, the store's retention, and an association pool whose
// threads each serve one association (store_association).
#include "net/store_scp.hpp"

#include "net/association_pool.hpp"
#include "net/dcmtk_quiet.hpp"
#include "net/store_association.hpp"
#include "net/store_retention.hpp"

#include <algorithm>
#include <chrono>
#include <dcmtk/config/osconfig.h> // must come first among DCMTK's headers
#include <dcmtk/dcmnet/dcmtrans.h>
#include <dcmtk/dcmnet/dul.h>
#include <system_error>

namespace steerseg::net {

bool isSafeUid(const std::string& uid) {
    return !uid.empty() && uid.size() <= 64 && uid.front() != '.' &&
           std::all_of(uid.begin(), uid.end(),
                       [](char c) { return (c >= '0' && c <= '9') || c == '.'; });
}

class StorageScp::Impl {
  public:
    Impl(ScpSettings settings, ScpReport report)
        : settings_(std::move(settings)), shared_(std::move(report)),
          pool_(settings_.port,
                {settings_.timeoutSeconds, settings_.negotiationSeconds,
                 AssociationPool::Limits{}.maxPending,
                 AssociationPool::Limits{}.maxPendingPerAddress, settings_.maxAssociations}) {}

    void open() {
        std::error_code ec;
        std::filesystem::create_directories(settings_.store, ec);
        if (ec) {
            throw ScpError("cannot create the store " + settings_.store.string() + ": " +
                           ec.message());
        }
        prune();
        if (settings_.tls) {
            try {
                tls_ = std::make_unique<TlsContext>(*settings_.tls, TlsRole::Acceptor);
            } catch (const TlsError& e) {
                throw ScpError(std::string("cannot listen with TLS: ") + e.what());
            }
        }
        try {
            pool_.open(tls_ ? tls_->context() : nullptr);
        } catch (const std::exception& e) {
            throw ScpError("cannot listen on port " + std::to_string(settings_.port) + ": " +
                           e.what());
        }
    }

    void serve(const std::atomic<bool>& stop) {
        shared_.stop = &stop;
        pool_.serve(
            stop,
            [this](T_ASC_Association* assoc) { serveStoreAssociation(assoc, settings_, shared_); },
            [this](const std::string& aet, const std::string& address) {
                shared_.report("rejected association from " + aet + " at " + address + ": " +
                               std::to_string(settings_.maxAssociations) +
                               " association(s) open already (busy)");
            },
            [this] {
                // Only while no association is open: a series being written is never pruned.
                if (std::chrono::steady_clock::now() - lastPrune_ > std::chrono::hours(1)) {
                    prune();
                }
            },
            [this](const std::string& line) { shared_.report(line); });
    }

  private:
    void prune() {
        lastPrune_ = std::chrono::steady_clock::now();
        if (settings_.keepDays <= 0) {
            return;
        }
        if (const int n = pruneStore(settings_.store, std::chrono::hours(24 * settings_.keepDays));
            n > 0) {
            shared_.report("removed " + std::to_string(n) + " series older than " +
                           std::to_string(settings_.keepDays) + " day(s)");
        }
    }

    ScpSettings settings_;
    StoreShared shared_;
    std::unique_ptr<TlsContext> tls_; // declared before pool_, whose network uses it
    AssociationPool pool_;
    std::chrono::steady_clock::time_point lastPrune_;
};

StorageScp::StorageScp(ScpSettings settings, ScpReport report) {
    quietDcmtk();
    // The caller's numeric address, as AllowedCaller::host names it, and no DNS wait.
    dcmDisableGethostbyaddr.set(OFTrue);
    if (settings.tls) {
        // An association's blocking reads over TLS are bounded by the socket's receive timeout
        // (DCMTK's default 60 s, for the whole process) as well as by the DIMSE timeout: the
        // same as the latter. (The handshake itself is the pool's, within
        // negotiationSeconds.)
        dcmSocketReceiveTimeout.set(settings.timeoutSeconds);
    }
    impl_ = std::make_unique<Impl>(std::move(settings), std::move(report));
}

StorageScp::~StorageScp() = default;

void StorageScp::open() {
    impl_->open();
}

void StorageScp::serve(const std::atomic<bool>& stop) {
    impl_->serve(stop);
}

} // namespace steerseg::net
