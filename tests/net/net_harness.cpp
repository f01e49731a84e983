#include "net/net_harness.hpp"

#include "workflow/audit_log.hpp"

#include <arpa/inet.h>
#include <csignal>
#include <fcntl.h>
#include <fstream>
#include <netinet/in.h>
#include <stdexcept>
#include <sys/socket.h>
#include <sys/wait.h>
#include <thread>
#include <unistd.h>

namespace steerseg::test {
namespace {

int loopbackSocket(int port, bool connectTo) {
    const int fd = ::socket(AF_INET, SOCK_STREAM | SOCK_CLOEXEC, 0);
    if (fd < 0) {
        return -1;
    }
    sockaddr_in addr{};
    addr.sin_family = AF_INET;
    addr.sin_port = htons(static_cast<std::uint16_t>(port));
    addr.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
    const auto* a = reinterpret_cast<const sockaddr*>(&addr);
    if ((connectTo ? ::connect(fd, a, sizeof addr) : ::bind(fd, a, sizeof addr)) != 0) {
        ::close(fd);
        return -1;
    }
    return fd;
}

// argv[0] found on PATH, both output streams appended to `log`.
pid_t spawn(const std::vector<std::string>& argv, const std::filesystem::path& log) {
    std::vector<char*> args;
    for (const auto& a : argv) {
        args.push_back(const_cast<char*>(a.c_str()));
    }
    args.push_back(nullptr);
    const pid_t pid = ::fork();
    if (pid < 0) {
        throw std::runtime_error("fork failed");
    }
    if (pid == 0) {
        const int fd = ::open(log.c_str(), O_WRONLY | O_CREAT | O_APPEND, 0644);
        if (fd >= 0) {
            ::dup2(fd, 1);
            ::dup2(fd, 2);
        }
        ::execvp(args[0], args.data());
        ::_exit(127);
    }
    return pid;
}

} // namespace

int connectLoopback(int port) {
    return loopbackSocket(port, true);
}

int freePort() {
    const int fd = loopbackSocket(0, false);
    if (fd < 0) {
        throw std::runtime_error("cannot bind a loopback socket");
    }
    sockaddr_in addr{};
    socklen_t length = sizeof addr;
    ::getsockname(fd, reinterpret_cast<sockaddr*>(&addr), &length);
    ::close(fd);
    return ntohs(addr.sin_port);
}

bool waitUntil(const std::function<bool()>& ready, std::chrono::milliseconds timeout) {
    const auto end = std::chrono::steady_clock::now() + timeout;
    while (!ready()) {
        if (std::chrono::steady_clock::now() > end) {
            return false;
        }
        std::this_thread::sleep_for(std::chrono::milliseconds(50));
    }
    return true;
}

ChildProcess::ChildProcess(const std::vector<std::string>& argv, const std::filesystem::path& log)
    : pid_(spawn(argv, log)), log_(log) {}

ChildProcess::~ChildProcess() {
    if (pid_ > 0) {
        stop();
    }
}

bool ChildProcess::running() {
    if (pid_ <= 0) {
        return false;
    }
    int status = 0;
    if (::waitpid(pid_, &status, WNOHANG) == pid_) {
        pid_ = -1;
        return false;
    }
    return true;
}

void ChildProcess::killHard() {
    if (pid_ > 0) {
        ::kill(pid_, SIGKILL);
    }
}

void ChildProcess::signal(int number) {
    if (pid_ > 0) {
        ::kill(pid_, number);
    }
}

int ChildProcess::stop() {
    if (pid_ <= 0) {
        return -1;
    }
    ::kill(pid_, SIGTERM);
    int status = 0;
    const bool exited = waitUntil([&] { return ::waitpid(pid_, &status, WNOHANG) == pid_; },
                                  std::chrono::seconds(10));
    if (!exited) {
        ::kill(pid_, SIGKILL);
        ::waitpid(pid_, &status, 0);
    }
    pid_ = -1;
    return exited && WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

Finished runProgram(const std::vector<std::string>& argv, const std::filesystem::path& folder) {
    static int counter = 0;
    const auto log = folder / ("run-" + std::to_string(counter++) + ".log");
    int status = 0;
    ::waitpid(spawn(argv, log), &status, 0);
    return {WIFEXITED(status) ? WEXITSTATUS(status) : -1, readText(log)};
}

std::optional<std::string> httpGet(int port, const std::string& path) {
    const int fd = loopbackSocket(port, true);
    if (fd < 0) {
        return std::nullopt;
    }
    const std::string request =
        "GET " + path + " HTTP/1.1\r\nHost: 127.0.0.1\r\nConnection: close\r\n\r\n";
    if (::send(fd, request.data(), request.size(), MSG_NOSIGNAL) !=
        static_cast<ssize_t>(request.size())) {
        ::close(fd);
        return std::nullopt;
    }
    std::string response;
    char buffer[65536];
    ssize_t n = 0;
    while ((n = ::recv(fd, buffer, sizeof buffer, 0)) > 0) {
        response.append(buffer, static_cast<std::size_t>(n));
    }
    ::close(fd);
    const auto headerEnd = response.find("\r\n\r\n");
    if (response.rfind("HTTP/1.1 200", 0) != 0 || headerEnd == std::string::npos) {
        return std::nullopt;
    }
    // Orthanc answers a Connection: close request with a length, never chunked.
    return response.substr(headerEnd + 4);
}

OrthancServer::OrthancServer(const std::filesystem::path& folder, const nlohmann::json& extra)
    : folder_(folder), dicomPort_(freePort()), httpPort_(freePort()) {
    nlohmann::json config = {
        {"Name", "steerseg-test"},
        {"StorageDirectory", (folder / "storage").string()},
        {"IndexDirectory", (folder / "storage").string()},
        {"DicomAet", kAet},
        {"DicomPort", dicomPort_},
        {"HttpPort", httpPort_},
        {"RemoteAccessAllowed", false},
        {"AuthenticationEnabled", false},
        {"DicomCheckCalledAet", true},
        {"Plugins", nlohmann::json::array()},
        {"SaveJobs", false},
        {"StableAge", 1},
    };
    config.update(extra);
    std::ofstream(folder / "orthanc.json") << config.dump(2);
    start();
}

void OrthancServer::start() {
    process_.emplace(std::vector<std::string>{kProgram, (folder_ / "orthanc.json").string()},
                     folder_ / "orthanc.log");
    if (!waitUntil([&] { return httpGet(httpPort_, "/system").has_value(); },
                   std::chrono::seconds(20))) {
        throw std::runtime_error("Orthanc did not come up: " + process_->log());
    }
}

void OrthancServer::stop() {
    process_.reset();
}

nlohmann::json OrthancServer::get(const std::string& path) const {
    const auto body = httpGet(httpPort_, path);
    if (!body) {
        throw std::runtime_error("GET " + path + " from Orthanc failed");
    }
    return nlohmann::json::parse(*body);
}

// A PDU or item (PS3.8 9.3): type, a reserved byte, the body's length big-endian in `lengthBytes`.
static std::string pduItem(int type, const std::string& body, int lengthBytes = 2) {
    std::string s{static_cast<char>(type), '\0'};
    for (int shift = 8 * (lengthBytes - 1); shift >= 0; shift -= 8) {
        s += static_cast<char>((body.size() >> shift) & 0xff);
    }
    return s + body;
}

// An A-ASSOCIATE-RQ for Verification in implicit little endian (PS3.8 9.3.2).
std::string associateRequest(const std::string& calling, const std::string& called) {
    const auto ae = [](std::string a) {
        a.resize(16, ' ');
        return a;
    };
    const std::string context = std::string("\x01\0\0\0", 4) + pduItem(0x30, "1.2.840.10008.1.1") +
                                pduItem(0x40, "1.2.840.10008.1.2");
    const std::string variable = pduItem(0x10, "1.2.840.10008.3.1.1.1") + pduItem(0x20, context) +
                                 pduItem(0x50, pduItem(0x51, std::string("\0\0\x40\0", 4)));
    return pduItem(0x01,
                   std::string("\0\x01\0\0", 4) + ae(called) + ae(calling) + std::string(32, '\0') +
                       variable,
                   4);
}

ListenProcess::ListenProcess(const std::filesystem::path& folder,
                             const std::vector<std::string>& extra)
    : dir(folder) {
    std::vector<std::string> argv{steersegBinary().string(), "listen",  "--port",
                                  std::to_string(port),      "--store", (dir / "store").string()};
    argv.insert(argv.end(), extra.begin(), extra.end());
    process = std::make_unique<ChildProcess>(argv, dir / "listen.log");
    if (!waitUntil([&] { return log().find("listening as") != std::string::npos; },
                   std::chrono::seconds(10))) {
        throw std::runtime_error("steerseg listen did not start: " + log());
    }
}

std::string ListenProcess::log() const {
    return readText(dir / "listen.log");
}

Finished ListenProcess::storescu(const std::string& aet, const std::filesystem::path& input) const {
    return runProgram({"storescu", "-aet", aet, "-aec", "STEERSEG", "+sd", "127.0.0.1",
                       std::to_string(port), input.string()},
                      dir);
}

Finished ListenProcess::echo(const std::string& aet) const {
    return runProgram(
        {"echoscu", "-aet", aet, "-aec", "STEERSEG", "127.0.0.1", std::to_string(port)}, dir);
}

std::vector<std::filesystem::path> filesBelow(const std::filesystem::path& root) {
    std::vector<std::filesystem::path> found;
    if (!std::filesystem::exists(root)) {
        return found;
    }
    for (const auto& e : std::filesystem::recursive_directory_iterator(root)) {
        if (e.is_regular_file()) {
            found.push_back(e.path());
        }
    }
    return found;
}

SilentPeer::SilentPeer() {
    fd_ = ::socket(AF_INET, SOCK_STREAM | SOCK_CLOEXEC, 0);
    sockaddr_in addr{};
    addr.sin_family = AF_INET;
    addr.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
    addr.sin_port = 0;
    ::bind(fd_, reinterpret_cast<const sockaddr*>(&addr), sizeof addr);
    ::listen(fd_, 16);
    socklen_t length = sizeof addr;
    ::getsockname(fd_, reinterpret_cast<sockaddr*>(&addr), &length);
    port_ = ntohs(addr.sin_port);
}

SilentPeer::~SilentPeer() {
    ::close(fd_);
}

std::vector<nlohmann::json> auditRecords(const std::filesystem::path& audit,
                                         const std::string& event) {
    std::vector<nlohmann::json> out;
    for (nlohmann::json& r : workflow::readAuditLog(audit).records) {
        if (r.value("event", "") == event) {
            out.push_back(std::move(r));
        }
    }
    return out;
}

} // namespace steerseg::test
