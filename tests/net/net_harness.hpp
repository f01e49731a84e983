#pragma once

// What the network tests run against: real processes on 127.0.0.1 (Orthanc, `steerseg listen`,
// DCMTK's storescu and echoscu), each started on free loopback ports and stopped by the test.
#include "support/test_data.hpp"
#include "support/write_faults.hpp" // readText

#include <chrono>
#include <filesystem>
#include <functional>
#include <memory>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <sys/types.h>
#include <vector>

namespace steerseg::test {

// Skips the test where Orthanc or DCMTK's tools are missing, or fails it under
// STEERSEG_REQUIRE_DATA=1 (CI installs them: tools/install-deps.sh).
#define STEERSEG_REQUIRE_PROGRAM(path, package)                                                    \
    if (!std::filesystem::exists(path)) {                                                          \
        if (::steerseg::test::dataRequired()) {                                                    \
            GTEST_FAIL() << path << " is missing (Debian " << package                              \
                         << "; tools/install-deps.sh)";                                            \
        }                                                                                          \
        GTEST_SKIP() << path << " is missing (Debian " << package << "; tools/install-deps.sh)";   \
    }

// A TCP port on 127.0.0.1 that nothing listens on at the moment of asking.
int freePort();

// Polls `ready` every 50 ms until it holds or `timeout` passes.
bool waitUntil(const std::function<bool()>& ready, std::chrono::milliseconds timeout);

// The audit log's records of one event ("send", "query", ...), in order.
std::vector<nlohmann::json> auditRecords(const std::filesystem::path& audit,
                                         const std::string& event);

// A child process with stdout and stderr in `log`; SIGTERM and reaped by stop() or at the end.
// A TCP port on 127.0.0.1 that completes every connection (the kernel's backlog) and never says
// anything: the silent peer.
class SilentPeer {
  public:
    SilentPeer();
    ~SilentPeer();
    SilentPeer(const SilentPeer&) = delete;
    SilentPeer& operator=(const SilentPeer&) = delete;
    [[nodiscard]] int port() const { return port_; }

  private:
    int fd_ = -1;
    int port_ = 0;
};

class ChildProcess {
  public:
    ChildProcess(const std::vector<std::string>& argv, const std::filesystem::path& log);
    ~ChildProcess();
    ChildProcess(const ChildProcess&) = delete;
    ChildProcess& operator=(const ChildProcess&) = delete;
    // SIGTERM, then the exit status (-1 if it did not exit normally within 10 s: then SIGKILL).
    int stop();
    [[nodiscard]] bool running();
    // kill -9: no handler runs, nothing is flushed or cleaned up (stop() then reaps it).
    void killHard();
    // Any other signal (SIGSTOP to freeze a sender half way, SIGCONT).
    void signal(int number);
    [[nodiscard]] std::string log() const { return readText(log_); }

  private:
    pid_t pid_ = -1;
    std::filesystem::path log_;
};

// A TCP connection to 127.0.0.1:port (close-on-exec), or -1 when it cannot be made.
int connectLoopback(int port);

// An A-ASSOCIATE-RQ PDU for Verification in implicit little endian (PS3.8 9.3.2), as a raw
// client sends it (whole, half, or followed by nothing).
std::string associateRequest(const std::string& calling, const std::string& called);

// A program run to its end: exit status (-1 when killed) and its output, both streams.
struct Finished {
    int status = -1;
    std::string output;
};
Finished runProgram(const std::vector<std::string>& argv, const std::filesystem::path& folder);

// The body of GET http://127.0.0.1:port/path (HTTP/1.1, Connection: close), or nullopt when the
// connection fails or the status is not 200.
std::optional<std::string> httpGet(int port, const std::string& path);

// `steerseg listen` on a free port, storing into <dir>/store, output in <dir>/listen.log; the
// constructor returns once it listens (throws when it does not within 10 s).
struct ListenProcess {
    std::filesystem::path dir;
    int port = freePort();
    std::unique_ptr<ChildProcess> process;

    ListenProcess(const std::filesystem::path& folder, const std::vector<std::string>& extra);
    [[nodiscard]] std::string log() const;
    Finished storescu(const std::string& aet, const std::filesystem::path& input) const;
    Finished echo(const std::string& aet) const;
};

// Every regular file below `root`, hidden ones (a write's temporary) included.
std::vector<std::filesystem::path> filesBelow(const std::filesystem::path& root);

// Orthanc (Debian's package) with its own configuration and storage in `folder`: DICOM and HTTP
// on free loopback ports, no remote access, no plug-ins. Waits for its REST API. `extra`'s keys
// are added to its configuration (DICOM TLS, modalities).
class OrthancServer {
  public:
    static constexpr const char* kAet = "ORTHANC";
    static constexpr const char* kProgram = "/usr/sbin/Orthanc";
    explicit OrthancServer(const std::filesystem::path& folder,
                           const nlohmann::json& extra = nlohmann::json::object());
    // Starts it again on the same ports and storage (after stop()); throws if it does not come up.
    void start();
    void stop();
    [[nodiscard]] int dicomPort() const { return dicomPort_; }
    [[nodiscard]] int httpPort() const { return httpPort_; }
    // GET of the REST API as JSON; throws when it fails.
    nlohmann::json get(const std::string& path) const;

  private:
    std::filesystem::path folder_;
    int dicomPort_ = 0;
    int httpPort_ = 0;
    std::optional<ChildProcess> process_;
};

} // namespace steerseg::test
