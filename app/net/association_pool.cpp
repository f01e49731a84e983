#include "net/association_pool.hpp"

#include "net/association_pdu.hpp"
#include "net/association_tls.hpp"
#include "net/port_socket.hpp"

#include <algorithm>
#include <arpa/inet.h>
#include <cerrno>
#include <cstring>
#include <dcmtk/config/osconfig.h> // must come first among DCMTK's headers
#include <dcmtk/dcmnet/assoc.h>
#include <dcmtk/dcmnet/dcmlayer.h>
#include <dcmtk/dcmnet/dcmtrans.h>
#include <dcmtk/dcmnet/dntypes.h>
#include <dcmtk/dcmnet/dul.h>
#include <fcntl.h>
#include <mutex>
#include <netinet/in.h>
#include <openssl/ssl.h>
#include <stdexcept>
#include <sys/ioctl.h>
#include <sys/socket.h>
#include <system_error>
#include <unistd.h>
#include <utility>

namespace steerseg::net {

namespace {

using Clock = std::chrono::steady_clock;

// DCMTK takes an accepted socket through one process-wide setting (its inetd mode): hold it
// only while DCMTK reads it, which it does at the start of ASC_receiveAssociation.
std::mutex externalSocketLock;

std::string peerAddress(int fd) {
    sockaddr_storage from{};
    socklen_t length = sizeof from;
    char text[INET6_ADDRSTRLEN] = "";
    if (::getpeername(fd, reinterpret_cast<sockaddr*>(&from), &length) == 0) {
        const void* address =
            from.ss_family == AF_INET6
                ? static_cast<const void*>(&reinterpret_cast<const sockaddr_in6*>(&from)->sin6_addr)
                : static_cast<const void*>(&reinterpret_cast<const sockaddr_in*>(&from)->sin_addr);
        ::inet_ntop(from.ss_family, address, text, sizeof text);
    }
    return text;
}

} // namespace

// DCMTK asks its network's transport layer for each connection's object; while the pool hands
// over a TLS connection (under externalSocketLock) that is the one it made ready.
class AssociationPool::HandOver : public DcmTransportLayer {
  public:
    DcmTransportConnection* createConnection(DcmNativeSocketType /*openSocket*/,
                                             OFBool /*useSecureLayer*/) override {
        return std::exchange(next, nullptr);
    }
    DcmTransportConnection* next = nullptr;
};

// Whether the connection's association request has arrived whole, read without taking it.
AssociationPool::Request AssociationPool::requestOf(int fd) {
    unsigned char head[kPduHead];
    const ssize_t n = ::recv(fd, head, sizeof head, MSG_PEEK | MSG_DONTWAIT);
    if (n == 0 || (n < 0 && errno != EAGAIN && errno != EWOULDBLOCK && errno != EINTR)) {
        return Request::Gone;
    }
    if (n <= 0) {
        return Request::Waiting;
    }
    if (head[0] != kAssociateRequest) {
        return Request::NotOne;
    }
    if (n < static_cast<ssize_t>(sizeof head)) {
        return Request::Waiting;
    }
    const std::uint32_t length = pduLength(head);
    if (length > kMaxRequestBytes) {
        return Request::NotOne;
    }
    int buffered = 0;
    if (::ioctl(fd, FIONREAD, &buffered) != 0) {
        return Request::Gone;
    }
    return static_cast<std::uint64_t>(buffered) >= sizeof head + std::uint64_t{length}
               ? Request::Whole
               : Request::Waiting;
}

void AssociationPool::discard(const Pending& p) {
    if (p.ssl != nullptr) {
        SSL_free(p.ssl);
    }
    ::close(p.fd);
}

AssociationPool::AssociationPool(int port, const Limits& limits) : port_(port), limits_(limits) {}

AssociationPool::~AssociationPool() {
    reap(true);
    for (const Pending& p : pending_) {
        discard(p);
    }
    if (network_ != nullptr) {
        ASC_dropNetwork(&network_);
    }
    if (listenFd_ >= 0) {
        ::close(listenFd_);
    }
}

void AssociationPool::open(ssl_ctx_st* tls) {
    std::string problem;
    listenFd_ = bindPort(port_, SOCK_NONBLOCK, problem);
    if (listenFd_ < 0) {
        throw std::runtime_error(problem);
    }
    if (::listen(listenFd_, 128) != 0) {
        throw std::runtime_error(std::strerror(errno));
    }
    // An acceptor network without a listening socket of its own (DCMTK creates none while an
    // external socket is set): it only ever reads the connections this pool hands it.
    OFCondition c;
    {
        const std::lock_guard lock(externalSocketLock);
        dcmExternalSocketHandle.set(listenFd_);
        c = ASC_initializeNetwork(NET_ACCEPTOR, port_, limits_.acseTimeoutSeconds, &network_);
        dcmExternalSocketHandle.set(DCMNET_INVALID_SOCKET);
    }
    if (c.bad()) {
        network_ = nullptr;
        throw std::runtime_error(c.text());
    }
    if (tls != nullptr) {
        handOver_ = std::make_unique<HandOver>();
        c = ASC_setTransportLayer(network_, handOver_.get(), 0);
        if (c.bad()) {
            throw std::runtime_error(std::string("TLS: ") + c.text());
        }
        tls_ = tls;
    }
}

void AssociationPool::reap(bool all) {
    for (auto it = workers_.begin(); it != workers_.end();) {
        if (all || it->done) {
            it->thread.join();
            if (it->socket >= 0) {
                ::close(it->socket);
            }
            it = workers_.erase(it);
        } else {
            ++it;
        }
    }
}

void AssociationPool::acceptConnections() {
    // At most a full house a call: a peer that reconnects as fast as it is pushed out must not
    // keep this loop from the requests.
    for (int n = 0; n < limits_.maxPending; ++n) {
        const int fd = ::accept4(listenFd_, nullptr, nullptr, SOCK_CLOEXEC | SOCK_NONBLOCK);
        if (fd < 0) {
            return; // none waiting (or the kernel's reason, tried again on the next wake)
        }
        Pending p;
        p.fd = fd;
        p.address = peerAddress(fd);
        p.deadline = Clock::now() + std::chrono::seconds(limits_.negotiationSeconds);
        const auto sameAddress = [&p](const Pending& q) { return q.address == p.address; };
        const auto full = [&] {
            return std::count_if(pending_.begin(), pending_.end(), sameAddress) >=
                       limits_.maxPendingPerAddress ||
                   static_cast<int>(pending_.size()) >= limits_.maxPending;
        };
        // A request that has arrived whole is taken, never pushed out: a flood from the
        // scanner's own address must not push the scanner's connection out.
        if (full()) {
            sweep();
        }
        if (full()) {
            // Past a cap the oldest goes: a connection that has said nothing for longest is the
            // likeliest to be a silent one, and the newest may be the scanner.
            const auto oldest = std::count_if(pending_.begin(), pending_.end(), sameAddress) >=
                                        limits_.maxPendingPerAddress
                                    ? std::find_if(pending_.begin(), pending_.end(), sameAddress)
                                    : pending_.begin();
            ++closed_[oldest->address + ": pushed out by newer ones before its association "
                                        "request"];
            discard(*oldest);
            pending_.erase(oldest);
        }
        pending_.push_back(std::move(p));
    }
}

void AssociationPool::waitForRequests() {
    std::vector<pollfd> fds{{listenFd_, POLLIN, 0}};
    auto wake = Clock::now() + std::chrono::seconds(1);
    for (const Pending& p : pending_) {
        fds.push_back({p.fd, p.events, 0});
        wake = std::min(wake, p.deadline);
    }
    // Requests already whole (taken by a sweep at a cap) are not kept waiting.
    const auto wait =
        ready_.empty() ? std::chrono::duration_cast<std::chrono::milliseconds>(wake - Clock::now())
                       : std::chrono::milliseconds(0);
    ::poll(fds.data(), fds.size(), static_cast<int>(std::max<std::int64_t>(wait.count(), 0)));
    sweep();
}

void AssociationPool::sweep() {
    const Clock::time_point now = Clock::now();
    std::vector<Pending> still;
    for (Pending& p : pending_) {
        std::string why;
        switch (tls_ != nullptr ? tlsRequest(p, why) : requestOf(p.fd)) {
        case Request::Whole:
            ready_.push_back(std::move(p));
            continue;
        case Request::Gone:
            discard(p);
            continue;
        case Request::NotOne:
            ++closed_[p.address + ": what it sent is no association request"];
            discard(p);
            continue;
        case Request::Refused:
            ++refusedTls_[p.address + ": TLS error: " + why];
            discard(p);
            continue;
        case Request::Waiting:
            break;
        }
        if (now >= p.deadline) {
            ++closed_[p.address +
                      (tls_ != nullptr && !p.handshaken ? ": no TLS handshake within "
                                                        : ": no association request within ") +
                      std::to_string(limits_.negotiationSeconds) + " s"];
            discard(p);
            continue;
        }
        still.push_back(std::move(p));
    }
    pending_ = std::move(still);
}

void AssociationPool::take(Pending& p, const Serve& serve, const Busy& busy,
                           const Refused& refused) {
    const int fd = p.fd;
    // DCMTK reads the socket blocking from here on: whole requests read at once.
    ::fcntl(fd, F_SETFL, ::fcntl(fd, F_GETFL, 0) & ~O_NONBLOCK);
    std::unique_ptr<DcmTransportConnection> ready;
    if (p.ssl != nullptr) {
        ready = readyTlsConnection(fd, std::exchange(p.ssl, nullptr), std::move(p.request));
    }
    T_ASC_Association* assoc = nullptr;
    OFCondition c;
    {
        const std::lock_guard lock(externalSocketLock);
        dcmExternalSocketHandle.set(fd);
        if (handOver_) {
            handOver_->next = ready.get();
        }
        c = ASC_receiveAssociation(network_, &assoc, ASC_DEFAULTMAXPDU, nullptr, nullptr,
                                   ready ? OFTrue : OFFalse, DUL_NOBLOCK,
                                   limits_.negotiationSeconds);
        dcmExternalSocketHandle.set(DCMNET_INVALID_SOCKET);
        if (handOver_ && handOver_->next == nullptr) {
            (void)ready.release(); // DCMTK's association owns it (and the socket) now
        } else if (handOver_) {
            handOver_->next = nullptr;
        }
    }
    if (c.bad()) {
        // A request DCMTK cannot parse: that connection ends, the node goes on. Whoever holds
        // the socket closes it (the connection object, while the pool still has it).
        if (assoc != nullptr && assoc->DULassociation != nullptr) {
            ASC_dropAssociation(assoc);
        } else if (!ready) {
            ::close(fd);
        }
        refused(std::string(tls_ != nullptr ? "refused TLS connection: " : "refused connection: ") +
                c.text());
        ASC_destroyAssociation(&assoc);
        return;
    }
    admit(assoc, fd, serve, busy);
}

void AssociationPool::admit(T_ASC_Association* assoc, int fd, const Serve& serve,
                            const Busy& busy) {
    if (workers_.size() >= static_cast<std::size_t>(limits_.maxAssociations)) {
        T_ASC_RejectParameters reject{ASC_RESULT_REJECTEDTRANSIENT,
                                      ASC_SOURCE_SERVICEPROVIDER_PRESENTATION_RELATED,
                                      ASC_REASON_SP_PRES_LOCALLIMITEXCEEDED};
        ASC_rejectAssociation(assoc, &reject);
        busy(assoc->params->DULparams.callingAPTitle,
             assoc->params->DULparams.callingPresentationAddress);
        ASC_dropAssociation(assoc);
        ASC_destroyAssociation(&assoc);
        return;
    }
    Worker& worker = workers_.emplace_back();
    worker.socket = ::fcntl(fd, F_DUPFD_CLOEXEC, 0);
    try {
        worker.thread = std::thread([&serve, &worker, assoc] {
            serve(assoc);
            worker.done = true;
        });
    } catch (const std::system_error&) {
        // No thread to be had: as busy as can be.
        if (worker.socket >= 0) {
            ::close(worker.socket);
        }
        workers_.pop_back();
        busy(assoc->params->DULparams.callingAPTitle,
             assoc->params->DULparams.callingPresentationAddress);
        ASC_abortAssociation(assoc);
        ASC_destroyAssociation(&assoc);
    }
}

void AssociationPool::serve(const std::atomic<bool>& stop, const Serve& serve, const Busy& busy,
                            const Idle& idle, const Refused& refused) {
    while (!stop) {
        reap(false);
        if (workers_.empty() && pending_.empty()) {
            idle();
        }
        acceptConnections();
        waitForRequests();
        acceptConnections();
        for (Pending& p : ready_) {
            take(p, serve, busy, refused);
        }
        ready_.clear();
        // One line a cause, not one a connection: a port scanner's fifty are one event.
        for (const auto& [why, count] : closed_) {
            refused("closed " + std::to_string(count) + " connection(s) from " + why);
        }
        closed_.clear();
        for (const auto& [why, count] : refusedTls_) {
            refused("refused TLS connection from " + why +
                    (count > 1 ? " (" + std::to_string(count) + " times)" : ""));
        }
        refusedTls_.clear();
    }
    for (const Pending& p : pending_) {
        discard(p);
    }
    pending_.clear();
    // The associations still open end now: their reads fail at once, and each thread aborts
    // its association and leaves no object half written (store_association writes whole ones).
    for (const Worker& w : workers_) {
        if (!w.done && w.socket >= 0) {
            ::shutdown(w.socket, SHUT_RDWR);
        }
    }
    reap(true);
}

} // namespace steerseg::net
