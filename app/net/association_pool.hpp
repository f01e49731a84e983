#pragma once

// Accepts DICOM associations on a port and hands each to a thread of its own, at most `max` at
// once. DCMTK's DcmSCPPool does the same but builds its workers without arguments and keeps
// them past their association; this one gives each its settings and joins it when it ends.
#include <atomic>
#include <functional>
#include <list>
#include <string>
#include <thread>

class DcmTransportLayer;
struct T_ASC_Association;
struct T_ASC_Network;

namespace steerseg::net {

class AssociationPool {
  public:
    // `serve` runs on the association's own thread and owns `assoc` (drops and destroys it).
    using Serve = std::function<void(T_ASC_Association* assoc)>;
    // One more association than `max`: told to `busy` with the caller's AE title and address,
    // after it has been rejected.
    using Busy = std::function<void(const std::string& callingAet, const std::string& address)>;
    // Once a second while no association is open (retention runs there).
    using Idle = std::function<void()>;
    // A TLS connection that ended before its association request (its certificate refused, or
    // no TLS at all), with DCMTK's reason.
    using Refused = std::function<void(const std::string& why)>;

    AssociationPool(int port, int acseTimeoutSeconds, int max);
    ~AssociationPool(); // joins the threads left (serve() normally has)
    AssociationPool(const AssociationPool&) = delete;
    AssociationPool& operator=(const AssociationPool&) = delete;

    // Binds the port; throws std::runtime_error with DCMTK's reason when it cannot. With `tls`
    // (not owned; it must outlive the pool) every connection is TLS.
    void open(DcmTransportLayer* tls = nullptr);
    // Until `stop` becomes true (checked at least once a second); then joins the associations'
    // threads, each ending by itself (its peer's release or abort, or the DIMSE timeout).
    void serve(const std::atomic<bool>& stop, const Serve& serve, const Busy& busy,
               const Idle& idle, const Refused& refused);

  private:
    struct Worker {
        std::thread thread;
        std::atomic<bool> done{false};
    };
    void reap(bool all);

    int port_;
    int acseTimeoutSeconds_;
    int max_;
    T_ASC_Network* network_ = nullptr;
    bool secure_ = false;
    std::list<Worker> workers_;
};

} // namespace steerseg::net
