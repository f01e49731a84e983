#pragma once

// The kiosk's PACS search and retrieve (docs/dicom-network.md "The kiosk's search"): what the
// workflow accepted as SearchPacs, ListPacsSeries, RetrievePacs and CancelRetrieve, run on two
// threads of their own (the searches and series listings on one, the retrieve on the other: a
// search may go while a retrieve runs), every answer bounded by [dicom]
// query_timeout_seconds. The frame thread hands requests in and takes the results out under a
// lock once a frame; it never waits for the network. Part of the kiosk's DICOM node (full
// build only: it needs DCMTK).
#include "config/kiosk_config.hpp"
#include "model/action.hpp"
#include "workflow/status.hpp"

#include <atomic>
#include <condition_variable>
#include <mutex>
#include <nlohmann/json.hpp>
#include <optional>
#include <ostream>
#include <string>
#include <thread>
#include <utility>
#include <vector>

namespace steerseg::workflow {
class AuditLog;
}

namespace steerseg::kiosk {

class PacsClient {
  public:
    // `listening`: the node's Storage SCP is open, so a C-MOVE's images have somewhere to go.
    PacsClient(const config::DicomConfig& dicom, bool listening);
    // Cancels a retrieve under way and joins both threads (within the timeout at worst).
    ~PacsClient();
    PacsClient(const PacsClient&) = delete;
    PacsClient& operator=(const PacsClient&) = delete;

    // The frame thread: one accepted PACS action. A search or series listing while one runs
    // waits for it (the newest of each only); a retrieve while one runs is refused with a line
    // (cancel it first).
    void request(const model::Action& action);
    // The frame thread: the threads' lines to `err`, their audit records to `audit`, and the
    // state for show().
    void take(workflow::AuditLog& audit, std::ostream& err, const char* prefix);
    void show(workflow::PacsView& view) const { view = shown_; }
    void stop();

  private:
    struct Shared {
        std::optional<model::SearchPacs> search;     // waiting for the search thread
        std::optional<model::ListPacsSeries> series; // waiting for the search thread too
        std::optional<model::RetrievePacs> retrieve; // waiting for the retrieve thread
        workflow::PacsView view;
        std::vector<std::string> log;
        std::vector<std::pair<std::string, nlohmann::json>> audit;
    };

    void searchLoop();
    void retrieveLoop();
    void runSearch(const model::SearchPacs& request);
    void runSeries(const model::ListPacsSeries& request);
    void runRetrieve(const model::RetrievePacs& request);
    [[nodiscard]] std::string peerName(const std::string& asked) const;

    config::DicomConfig dicom_;
    std::vector<std::string> queryPeers_; // the names with query = true, in the config's order
    bool listening_;
    std::atomic<bool> stop_{false};
    std::atomic<bool> cancel_{false};
    mutable std::mutex mutex_;
    std::condition_variable wake_;
    Shared shared_;
    workflow::PacsView shown_; // the frame thread's copy
    std::thread searchThread_;
    std::thread retrieveThread_;
};

} // namespace steerseg::kiosk
