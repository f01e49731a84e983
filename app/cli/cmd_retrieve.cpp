// `steerseg retrieve`: a study or one series from a configured PACS into the incoming store,
// by the peer's `retrieve` method (docs/dicom-network.md): C-GET on the request's association,
// or C-MOVE to the node's own AE title with the node's Storage SCP listening on its port in
// this process meanwhile. Progress on stderr, the series stored on stdout; SIGINT or SIGTERM
// cancels (C-CANCEL).
#include "cli/args.hpp"
#include "cli/commands.hpp"
#include "cli/dicom_options.hpp"
#include "net/received_series.hpp"
#include "net/retrieve_scu.hpp"
#include "net/store_scp.hpp"

#include <atomic>
#include <csignal>
#include <cstdio>
#include <stdexcept>
#include <thread>

namespace steerseg::cli {
namespace {

std::atomic<bool> cancelRequested{false};
static_assert(std::atomic<bool>::is_always_lock_free, "set from a signal handler");

// C linkage has no namespace: the name must differ from the other commands' handlers.
extern "C" void onRetrieveCancelSignal(int /*signal*/) {
    cancelRequested.store(true);
}

void printProgress(const net::RetrieveProgress& p) {
    if (p.expected > 0) {
        std::fprintf(stderr, "received %d of %d images%s\n", p.received, p.expected,
                     p.failed > 0 ? (", " + std::to_string(p.failed) + " failed").c_str() : "");
    } else {
        std::fprintf(stderr, "received %d image(s)\n", p.received);
    }
}

// The C-MOVE's images arrive on the node's own port: its Storage SCP (the one `listen` and the
// kiosk run) takes them from this peer only, for as long as the retrieve runs.
class MoveReceiver {
  public:
    MoveReceiver(const config::DicomConfig& dicom, const kiosk::QueryPeer& from,
                 const std::filesystem::path& store)
        : scp_(settings(dicom, from, store), [](const std::string& line) {
              if (line.rfind("stored ", 0) != 0) {
                  std::fprintf(stderr, "%s\n", line.c_str());
              }
          }) {
        try {
            scp_.open();
        } catch (const net::ScpError& e) {
            throw std::runtime_error(
                std::string("cannot receive the moved images: ") + e.what() +
                " (a running kiosk node or `steerseg listen` holds the port: stop it for the "
                "retrieve, or give the peer retrieve = \"get\")");
        }
        thread_ = std::thread([this] { scp_.serve(stop_); });
    }
    ~MoveReceiver() {
        stop_.store(true);
        thread_.join();
    }
    MoveReceiver(const MoveReceiver&) = delete;
    MoveReceiver& operator=(const MoveReceiver&) = delete;

  private:
    static net::ScpSettings settings(const config::DicomConfig& dicom, const kiosk::QueryPeer& from,
                                     const std::filesystem::path& store) {
        net::ScpSettings s = kiosk::scpSettings(dicom);
        s.store = store;
        s.allowed = {{from.peer.aet, from.address}};
        return s;
    }

    std::atomic<bool> stop_{false};
    net::StorageScp scp_;
    std::thread thread_;
};

} // namespace

int runRetrieve(std::span<const std::string> words) {
    const Args args(words, {"to", "study", "series", "store", "config", "timeout"}, {});
    if (!args.positional().empty()) {
        throw UsageError("unexpected '" + args.positional().front() + "'");
    }
    const config::KioskConfig cfg = nodeConfig(args);
    const kiosk::QueryPeer target = requireQueryPeer(args, cfg.dicom);
    const auto study = args.value("study");
    if (!study) {
        throw UsageError("give --study UID (`steerseg query --to PEER` finds it)");
    }
    const net::RetrieveRequest request{*study, args.value("series").value_or("")};
    if (const std::string problem = net::retrieveRequestProblem(request); !problem.empty()) {
        throw UsageError(problem);
    }
    net::ScuOptions options = kiosk::sendOptions(cfg.dicom);
    options.timeoutSeconds = scuTimeoutSeconds(args);
    net::RetrieveOptions how;
    how.method = target.retrieve;
    how.store = args.value("store").value_or(cfg.dicom.store.string());
    how.minFreeBytes = static_cast<std::uint64_t>(cfg.dicom.minFreeMb) << 20;
    how.moveDestination = cfg.dicom.aet;

    struct sigaction action {};
    action.sa_handler = onRetrieveCancelSignal;
    sigemptyset(&action.sa_mask);
    sigaction(SIGTERM, &action, nullptr);
    sigaction(SIGINT, &action, nullptr);
    const auto cancel = [] { return cancelRequested.load(); };
    net::RetrieveOutcome outcome;
    if (how.method == net::RetrieveMethod::Move) {
        const MoveReceiver receiver(cfg.dicom, target, how.store);
        outcome = net::retrieve(target.peer, request, how, options, printProgress, cancel);
    } else {
        outcome = net::retrieve(target.peer, request, how, options, printProgress, cancel);
    }
    // What the load screen will list: the series of this study now in the store.
    for (const auto& series : net::listReceivedSeries(how.store, std::chrono::seconds(0))) {
        const auto& folder = series.folder;
        if (folder.parent_path().filename() == request.studyUid &&
            (request.seriesUid.empty() || folder.filename() == request.seriesUid)) {
            std::printf("stored %s: %s\n", folder.c_str(), net::describe(series).c_str());
        }
    }
    std::fflush(stdout);
    if (!outcome.problem.empty()) {
        throw std::runtime_error(outcome.problem);
    }
    return kExitOk;
}

} // namespace steerseg::cli
