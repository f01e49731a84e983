#pragma once

// The sending side: DICOM files to a peer over one association (C-STORE SCU, DCMTK's dcmnet),
// and C-ECHO to ask whether a peer answers.
#include "net/dicom_peer.hpp"
#include "net/scu_options.hpp"

#include <filesystem>
#include <span>
#include <string>
#include <vector>

namespace steerseg::net {

// What became of one file. `accepted`: the peer answered success or a warning (PS3.4 B.2.3:
// 0x0000, 0xB000, 0xB006, 0xB007); otherwise `problem` says why in one line: the file cannot be
// read, the connection was refused, the association was rejected, no presentation context fits,
// or the peer's failure status.
struct SendOutcome {
    std::filesystem::path file;
    std::string sopInstanceUid; // "" when the file could not be read
    bool accepted = false;
    int status = -1; // the peer's DIMSE status, -1 when none came back
    std::string problem;
};

// The calling AE title, the timeouts and the TLS credentials, as for every call the node makes.
using SendOptions = ScuOptions;

// Sends each file once, in order, over one association; never throws for the network or the
// files (each outcome says what happened), so a caller can retry only the ones that failed.
std::vector<SendOutcome> sendFiles(const DicomPeer& peer,
                                   std::span<const std::filesystem::path> files,
                                   const SendOptions& options);

// C-ECHO: "" when the peer answered success, else why not in one line.
std::string echo(const DicomPeer& peer, const SendOptions& options);

} // namespace steerseg::net
