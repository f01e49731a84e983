// `steerseg listen`: the Storage SCP alone, in the foreground until SIGTERM or SIGINT, one line
// per event on stdout (docs/dicom-network.md).
#include "cli/args.hpp"
#include "cli/commands.hpp"
#include "cli/dicom_options.hpp"
#include "net/received_series.hpp"
#include "net/store_scp.hpp"

#include <atomic>
#include <chrono>
#include <csignal>
#include <cstdio>

namespace steerseg::cli {
namespace {

std::atomic<bool> stopRequested{false};
static_assert(std::atomic<bool>::is_always_lock_free, "set from a signal handler");

// C linkage has no namespace: the name must differ from the kiosk's own handler's.
extern "C" void onListenStopSignal(int /*signal*/) {
    stopRequested.store(true);
}

void printLine(const std::string& line) {
    std::printf("%s\n", line.c_str());
    std::fflush(stdout);
}

} // namespace

int runListen(std::span<const std::string> words) {
    const Args args(words, {"config", "aet", "port", "store", "allow", "quota-mb"}, {"tls"});
    const net::ScpSettings settings = listenSettings(args, nodeConfig(args).dicom);
    net::StorageScp scp(settings, printLine);
    scp.open();
    struct sigaction action {};
    action.sa_handler = onListenStopSignal;
    sigemptyset(&action.sa_mask);
    sigaction(SIGTERM, &action, nullptr);
    sigaction(SIGINT, &action, nullptr);
    printLine("listening as " + settings.aet + " on port " + std::to_string(settings.port) +
              (settings.tls ? " (TLS)" : "") + ", storing into " + settings.store.string());
    // What an earlier run (or a kill) left unfinished, so that nobody takes it for whole.
    for (const net::ReceivedSeries& s :
         net::listReceivedSeries(settings.store, std::chrono::seconds(0))) {
        if (s.incomplete) {
            printLine("incomplete series " + s.folder.lexically_relative(settings.store).string() +
                      ": " + net::describe(s));
        }
    }
    scp.serve(stopRequested);
    printLine("stopped");
    return kExitOk;
}

} // namespace steerseg::cli
