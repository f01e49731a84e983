#pragma once

// Accepts DICOM associations on a port and hands each to a thread of its own, at most `max` at
// once. DCMTK's DcmSCPPool does the same but builds its workers without arguments and keeps
// them past their association; this one gives each its settings and joins it when it ends.
// The listening socket is the pool's own (issue 48): DCMTK reads an A-ASSOCIATE-RQ on the
// thread that accepted its connection, for as long as its ACSE timeout, so one connection that
// says nothing held up every caller behind it. Here a new connection waits among the others,
// each with its own short deadline and within caps per address and in all, until its request
// has arrived whole; only then does DCMTK read it (from the socket handed over, which it then
// owns), at once. Over TLS the pool also runs each handshake itself, without blocking, beside
// the others and within the same deadline, and reads the request through it; DCMTK then gets
// the connection ready, the request's bytes first.
#include <atomic>
#include <chrono>
#include <functional>
#include <list>
#include <map>
#include <memory>
#include <poll.h>
#include <string>
#include <thread>
#include <vector>

struct T_ASC_Association;
struct T_ASC_Network;
struct ssl_ctx_st;
struct ssl_st;

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
    // A connection that ended before its association request was taken: no request within the
    // negotiation timeout, pushed out by newer ones past the caps, not an association request,
    // or a TLS connection refused (its certificate, or no TLS at all); one line why.
    using Refused = std::function<void(const std::string& why)>;

    struct Limits {
        int acseTimeoutSeconds = 30;  // an open association's silences
        int negotiationSeconds = 5;   // from a connection to its whole association request
        int maxPending = 64;          // connections still negotiating, in all ...
        int maxPendingPerAddress = 8; // ... and from one address; past either the oldest goes
        int maxAssociations = 4;      // served at once
    };

    AssociationPool(int port, const Limits& limits);
    ~AssociationPool(); // joins the threads left (serve() normally has)
    AssociationPool(const AssociationPool&) = delete;
    AssociationPool& operator=(const AssociationPool&) = delete;

    // Binds the port; throws std::runtime_error with the reason when it cannot. With `tls`
    // (OpenSSL's context, with the node's certificate and the trusted CAs; not owned, it must
    // outlive the pool) every connection is TLS.
    void open(ssl_ctx_st* tls = nullptr);
    // Until `stop` becomes true (checked at least once a second); then ends the open
    // associations (their connections shut down under them: a stop does not wait for a silent
    // peer's timeout) and joins their threads.
    void serve(const std::atomic<bool>& stop, const Serve& serve, const Busy& busy,
               const Idle& idle, const Refused& refused);

  private:
    struct Worker {
        std::thread thread;
        std::atomic<bool> done{false};
        // A second descriptor of the association's socket, which DCMTK owns and closes: shut
        // down through it at a stop, and closed after the join, so its number cannot meanwhile
        // name another socket.
        int socket = -1;
    };
    // A connection accepted whose association request has not arrived whole.
    struct Pending {
        int fd = -1;
        std::string address;
        std::chrono::steady_clock::time_point deadline;
        // TLS only: the handshake's state (then the connection's), whether it is done, the
        // request's bytes read through it so far, and what the handshake waits for (POLLIN or
        // POLLOUT).
        ssl_st* ssl = nullptr;
        bool handshaken = false;
        std::vector<unsigned char> request;
        short events = POLLIN;
    };
    enum class Request { Waiting, Whole, Gone, NotOne, Refused };
    static Request requestOf(int fd);
    Request tlsRequest(Pending& p, std::string& why) const;
    static void discard(const Pending& p);
    void reap(bool all);
    void acceptConnections();
    void waitForRequests();
    // Each pending connection's progress: whole requests to ready_, the failed and the
    // overdue closed.
    void sweep();
    void take(Pending& p, const Serve& serve, const Busy& busy, const Refused& refused);
    void admit(T_ASC_Association* assoc, int fd, const Serve& serve, const Busy& busy);

    int port_;
    Limits limits_;
    int listenFd_ = -1;
    T_ASC_Network* network_ = nullptr;
    ssl_ctx_st* tls_ = nullptr;
    // DCMTK's network takes its TLS connections from this: the one the pool made ready.
    class HandOver;
    std::unique_ptr<HandOver> handOver_;
    std::vector<Pending> pending_;
    std::vector<Pending> ready_;            // whose request is there, for take()
    std::map<std::string, int> closed_;     // connections closed before their request, by cause
    std::map<std::string, int> refusedTls_; // TLS handshakes failed, by address and reason
    std::list<Worker> workers_;
};

} // namespace steerseg::net
