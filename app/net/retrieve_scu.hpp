#pragma once

// Bringing a study or one series from a PACS into the node's incoming store (DCMTK's dcmnet,
// Study Root): by C-GET, where the images come back on the request's own association and are
// filed here exactly as the Storage SCP files a pushed series (store_filing), or by C-MOVE to
// the node's own AE title, where the PACS sends them to the node's port, whose Storage SCP
// files them (the caller makes sure one listens). Progress comes from the PACS's responses;
// every response must come within the timeout, and a cancel sends C-CANCEL.
#include "net/dicom_peer.hpp"
#include "net/scu_options.hpp"

#include <cstdint>
#include <filesystem>
#include <functional>
#include <string>

namespace steerseg::net {

enum class RetrieveMethod { Get, Move };

struct RetrieveRequest {
    std::string studyUid;
    std::string seriesUid; // "" = the whole study
};

struct RetrieveOptions {
    RetrieveMethod method = RetrieveMethod::Get;
    // C-GET: the incoming store the images are filed into, and the free space it keeps.
    std::filesystem::path store;
    std::uint64_t minFreeBytes = std::uint64_t{256} << 20;
    // C-MOVE: the AE title the PACS sends to (the node's own, which the PACS must know).
    std::string moveDestination;
};

// Images stored so far of those the PACS expects to send (completed + failed + warning +
// remaining in its latest response; 0 until it has said).
struct RetrieveProgress {
    int received = 0;
    int failed = 0;
    int expected = 0;
};

struct RetrieveOutcome {
    RetrieveProgress progress;
    bool cancelled = false; // the PACS ended it on our C-CANCEL
    std::string problem;    // "" = every image expected arrived
};

using RetrieveReport = std::function<void(const RetrieveProgress&)>;
// Asked between responses; true sends C-CANCEL (once) and waits for the PACS's last answer.
using RetrieveCancel = std::function<bool()>;

// "" when the request's UIDs are UIDs (digits and dots, at most 64), else why not.
std::string retrieveRequestProblem(const RetrieveRequest& request);

// Never throws for the network or the peer: the outcome says what happened.
RetrieveOutcome retrieve(const DicomPeer& peer, const RetrieveRequest& request,
                         const RetrieveOptions& retrieveOptions, const ScuOptions& options,
                         const RetrieveReport& report = {}, const RetrieveCancel& cancel = {});

} // namespace steerseg::net
