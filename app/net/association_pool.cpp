#include "net/association_pool.hpp"

#include "net/port_socket.hpp"

#include <algorithm>
#include <arpa/inet.h>
#include <cerrno>
#include <cstring>
#include <dcmtk/config/osconfig.h> // must come first among DCMTK's headers
#include <dcmtk/dcmnet/assoc.h>
#include <dcmtk/dcmnet/dntypes.h>
#include <dcmtk/dcmnet/dul.h>
#include <fcntl.h>
#include <mutex>
#include <netinet/in.h>
#include <poll.h>
#include <stdexcept>
#include <sys/ioctl.h>
#include <sys/socket.h>
#include <system_error>
#include <unistd.h>

namespace steerseg::net {

namespace {

using Clock = std::chrono::steady_clock;

// An association request larger than this is no scanner's (a few kilobytes at most).
constexpr std::uint32_t kMaxRequestBytes = 1U << 20;
constexpr unsigned char kAssociateRequest = 0x01; // the PDU type (PS3.8 9.3.2)

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

enum class Request { Waiting, Whole, Gone, NotOne };

// Whether the connection's association request has arrived whole, read without taking it.
// Over TLS the first bytes are the handshake's: their arrival is all that can be told here.
Request requestOf(int fd, bool secure) {
    unsigned char head[6];
    const ssize_t n = ::recv(fd, head, sizeof head, MSG_PEEK | MSG_DONTWAIT);
    if (n == 0 || (n < 0 && errno != EAGAIN && errno != EWOULDBLOCK && errno != EINTR)) {
        return Request::Gone;
    }
    if (n <= 0) {
        return Request::Waiting;
    }
    if (secure) {
        return Request::Whole;
    }
    if (head[0] != kAssociateRequest) {
        return Request::NotOne;
    }
    if (n < static_cast<ssize_t>(sizeof head)) {
        return Request::Waiting;
    }
    const std::uint32_t length = (std::uint32_t{head[2]} << 24U) | (std::uint32_t{head[3]} << 16U) |
                                 (std::uint32_t{head[4]} << 8U) | std::uint32_t{head[5]};
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

} // namespace

AssociationPool::AssociationPool(int port, const Limits& limits) : port_(port), limits_(limits) {}

AssociationPool::~AssociationPool() {
    reap(true);
    for (const Pending& p : pending_) {
        ::close(p.fd);
    }
    if (network_ != nullptr) {
        ASC_dropNetwork(&network_);
    }
    if (listenFd_ >= 0) {
        ::close(listenFd_);
    }
}

void AssociationPool::open(DcmTransportLayer* tls) {
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
        c = ASC_setTransportLayer(network_, tls, 0);
        if (c.bad()) {
            throw std::runtime_error(std::string("TLS: ") + c.text());
        }
        secure_ = true;
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
    for (;;) {
        const int fd = ::accept4(listenFd_, nullptr, nullptr, SOCK_CLOEXEC | SOCK_NONBLOCK);
        if (fd < 0) {
            return; // none waiting (or the kernel's reason, tried again on the next wake)
        }
        Pending p{fd, peerAddress(fd),
                  Clock::now() + std::chrono::seconds(limits_.negotiationSeconds)};
        // Past a cap the oldest goes: a connection that has said nothing for longest is the
        // likeliest to be a silent one, and the newest may be the scanner.
        const auto sameAddress = [&p](const Pending& q) { return q.address == p.address; };
        const auto fromThere = std::count_if(pending_.begin(), pending_.end(), sameAddress);
        const auto oldest =
            fromThere >= limits_.maxPendingPerAddress
                ? std::find_if(pending_.begin(), pending_.end(), sameAddress)
                : (static_cast<int>(pending_.size()) >= limits_.maxPending ? pending_.begin()
                                                                           : pending_.end());
        if (oldest != pending_.end()) {
            ++closed_[oldest->address + ": pushed out by newer ones before its association "
                                        "request"];
            ::close(oldest->fd);
            pending_.erase(oldest);
        }
        pending_.push_back(std::move(p));
    }
}

void AssociationPool::waitForRequests() {
    std::vector<pollfd> fds{{listenFd_, POLLIN, 0}};
    auto wake = Clock::now() + std::chrono::seconds(1);
    for (const Pending& p : pending_) {
        fds.push_back({p.fd, POLLIN, 0});
        wake = std::min(wake, p.deadline);
    }
    const auto wait = std::chrono::duration_cast<std::chrono::milliseconds>(wake - Clock::now());
    ::poll(fds.data(), fds.size(), static_cast<int>(std::max<std::int64_t>(wait.count(), 0)));
    const Clock::time_point now = Clock::now();
    std::vector<Pending> still;
    for (const Pending& p : pending_) {
        switch (requestOf(p.fd, secure_)) {
        case Request::Whole:
            ready_.push_back(p.fd);
            continue;
        case Request::Gone:
            ::close(p.fd);
            continue;
        case Request::NotOne:
            ++closed_[p.address + ": what it sent is no association request"];
            ::close(p.fd);
            continue;
        case Request::Waiting:
            break;
        }
        if (now >= p.deadline) {
            ++closed_[p.address + ": no association request within " +
                      std::to_string(limits_.negotiationSeconds) + " s"];
            ::close(p.fd);
            continue;
        }
        still.push_back(p);
    }
    pending_ = std::move(still);
}

void AssociationPool::take(int fd, const Serve& serve, const Busy& busy, const Refused& refused) {
    // DCMTK reads the socket blocking from here on: whole requests read at once.
    ::fcntl(fd, F_SETFL, ::fcntl(fd, F_GETFL, 0) & ~O_NONBLOCK);
    T_ASC_Association* assoc = nullptr;
    OFCondition c;
    {
        const std::lock_guard lock(externalSocketLock);
        dcmExternalSocketHandle.set(fd);
        c = ASC_receiveAssociation(network_, &assoc, ASC_DEFAULTMAXPDU, nullptr, nullptr,
                                   secure_ ? OFTrue : OFFalse, DUL_NOBLOCK,
                                   limits_.negotiationSeconds);
        dcmExternalSocketHandle.set(DCMNET_INVALID_SOCKET);
    }
    if (c.bad()) {
        // A failed TLS handshake, or a request DCMTK cannot parse: that connection ends, the
        // node goes on. Whoever holds the socket closes it.
        if (assoc != nullptr && assoc->DULassociation != nullptr) {
            ASC_dropAssociation(assoc);
        } else {
            ::close(fd);
        }
        refused(std::string(secure_ ? "refused TLS connection: " : "refused connection: ") +
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
        for (const int fd : ready_) {
            take(fd, serve, busy, refused);
        }
        ready_.clear();
        // One line a cause, not one a connection: a port scanner's fifty are one event.
        for (const auto& [why, count] : closed_) {
            refused("closed " + std::to_string(count) + " connection(s) from " + why);
        }
        closed_.clear();
    }
    for (const Pending& p : pending_) {
        ::close(p.fd);
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
