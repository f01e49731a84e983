// dcmnet's DcmSCU does the association; this file chooses the presentation contexts from the
// files' own SOP classes and transfer syntaxes and turns every condition into one line.
#include "net/store_scu.hpp"

#include "net/dcmtk_quiet.hpp"

#include <cstdio>
#include <dcmtk/config/osconfig.h> // must come first among DCMTK's headers
#include <dcmtk/dcmdata/dcdeftag.h>
#include <dcmtk/dcmdata/dcfilefo.h>
#include <dcmtk/dcmdata/dcmetinf.h>
#include <dcmtk/dcmdata/dcuid.h>
#include <dcmtk/dcmnet/scu.h>
#include <memory>
#include <optional>
#include <set>
#include <utility>

namespace steerseg::net {
namespace {

struct FileInfo {
    std::string sopClass;
    std::string sopInstance;
    std::string transferSyntax;
};

// The meta header only: the pixel data is read by DcmSCU when the file is sent.
std::optional<FileInfo> readMeta(const std::filesystem::path& path, std::string& problem) {
    DcmFileFormat file;
    const OFCondition c =
        file.loadFile(path.c_str(), EXS_Unknown, EGL_noChange, DCM_MaxReadLength, ERM_metaOnly);
    if (c.bad()) {
        problem = std::string("cannot be read as DICOM: ") + c.text();
        return std::nullopt;
    }
    OFString sopClass;
    OFString sopInstance;
    OFString xfer;
    DcmMetaInfo* meta = file.getMetaInfo();
    if (meta->findAndGetOFString(DCM_MediaStorageSOPClassUID, sopClass).bad() || sopClass.empty() ||
        meta->findAndGetOFString(DCM_MediaStorageSOPInstanceUID, sopInstance).bad() ||
        sopInstance.empty() || meta->findAndGetOFString(DCM_TransferSyntaxUID, xfer).bad() ||
        xfer.empty()) {
        problem = "has no DICOM file meta header with its SOP class, instance and transfer syntax";
        return std::nullopt;
    }
    return FileInfo{sopClass.c_str(), sopInstance.c_str(), xfer.c_str()};
}

// Warnings are stored objects (PS3.4 B.2.3); everything else is a failure.
bool acceptedStatus(Uint16 status) {
    return status == 0x0000 || status == 0xB000 || status == 0xB006 || status == 0xB007;
}

std::string hex(Uint16 status) {
    char text[8];
    std::snprintf(text, sizeof text, "0x%04X", static_cast<unsigned>(status));
    return text;
}

std::string statusMeaning(Uint16 status) {
    if ((status & 0xFF00) == 0xA700) {
        return "out of resources";
    }
    if ((status & 0xFF00) == 0xA900) {
        return "data set does not match SOP class";
    }
    if ((status & 0xF000) == 0xC000) {
        return "cannot understand";
    }
    if (status == 0x0122) {
        return "SOP class not supported";
    }
    if (status == 0x0124) {
        return "refused: not authorized";
    }
    return "failure";
}

std::string associationProblem(const DicomPeer& peer, const OFCondition& c) {
    std::string what = c.text();
    if (c == DUL_ASSOCIATIONREJECTED) {
        return "association rejected by " + describe(peer) + " (" + what + ")";
    }
    if (what.find("refused") != std::string::npos) {
        return "connection refused by " + describe(peer);
    }
    return "no association with " + describe(peer) + (peer.tls ? " over TLS: " : ": ") + what;
}

// DcmSCU keeps its TLS switch protected (for DcmTLSSCU, which would bring its own options).
class Scu : public DcmSCU {
  public:
    using DcmSCU::useSecureConnection;
};

// The network, TLS where the peer has it, the negotiation: "" or why not in one line. `tls`
// keeps the transport layer, which DCMTK does not own, alive beside `scu`.
std::string associate(Scu& scu, const DicomPeer& peer, const SendOptions& options,
                      std::unique_ptr<TlsContext>& tls) {
    OFCondition c = scu.initNetwork();
    if (c.good() && peer.tls) {
        try {
            tls = std::make_unique<TlsContext>(options.tls, TlsRole::Requestor, peer.host);
        } catch (const TlsError& e) {
            return "no TLS to " + describe(peer) + ": " + e.what();
        }
        c = scu.useSecureConnection(&tls->layer());
    }
    if (c.good()) {
        c = scu.negotiateAssociation();
    }
    return c.bad() ? associationProblem(peer, c) : "";
}

void configure(DcmSCU& scu, const DicomPeer& peer, const SendOptions& options) {
    scu.setAETitle(options.callingAet.c_str());
    scu.setPeerHostName(peer.host.c_str());
    scu.setPeerPort(static_cast<Uint16>(peer.port));
    scu.setPeerAETitle(peer.aet.c_str());
    scu.setConnectionTimeout(options.timeoutSeconds);
    scu.setACSETimeout(static_cast<Uint32>(options.timeoutSeconds));
    scu.setDIMSETimeout(static_cast<Uint32>(options.timeoutSeconds));
    scu.setDIMSEBlockingMode(DIMSE_NONBLOCKING);
    scu.setVerbosePCMode(OFFalse);
    scu.setProgressNotificationMode(OFFalse);
}

OFList<OFString> transferSyntaxes(const std::string& own) {
    OFList<OFString> list;
    list.push_back(own.c_str());
    for (const char* uid :
         {UID_LittleEndianExplicitTransferSyntax, UID_LittleEndianImplicitTransferSyntax}) {
        if (own != uid) {
            list.push_back(uid);
        }
    }
    return list;
}

} // namespace

std::vector<SendOutcome> sendFiles(const DicomPeer& peer,
                                   std::span<const std::filesystem::path> files,
                                   const SendOptions& options) {
    quietDcmtk();
    std::vector<SendOutcome> outcomes;
    std::vector<std::optional<FileInfo>> infos;
    std::set<std::pair<std::string, std::string>> contexts; // SOP class, transfer syntax
    for (const auto& path : files) {
        SendOutcome o;
        o.file = path;
        auto info = readMeta(path, o.problem);
        if (info) {
            o.sopInstanceUid = info->sopInstance;
            contexts.emplace(info->sopClass, info->transferSyntax);
        }
        outcomes.push_back(std::move(o));
        infos.push_back(std::move(info));
    }
    if (contexts.empty()) {
        return outcomes;
    }
    // DICOM allows 128 presentation contexts in one association (odd IDs 1..255).
    if (contexts.size() > 128) {
        for (auto& o : outcomes) {
            if (o.problem.empty()) {
                o.problem = "more than 128 kinds of object (SOP class and transfer syntax) for "
                            "one association";
            }
        }
        return outcomes;
    }
    std::unique_ptr<TlsContext> tls; // outlives scu, whose network uses it
    Scu scu;
    configure(scu, peer, options);
    // A peer that does not take a compressed syntax gets the object decompressed instead.
    scu.setDatasetConversionMode(OFTrue);
    for (const auto& [sopClass, xfer] : contexts) {
        scu.addPresentationContext(sopClass.c_str(), transferSyntaxes(xfer));
    }
    if (const std::string problem = associate(scu, peer, options, tls); !problem.empty()) {
        for (std::size_t n = 0; n < outcomes.size(); ++n) {
            if (infos[n]) {
                outcomes[n].problem = problem;
            }
        }
        return outcomes;
    }
    for (std::size_t n = 0; n < outcomes.size(); ++n) {
        if (!infos[n]) {
            continue;
        }
        SendOutcome& o = outcomes[n];
        if (!scu.isConnected()) {
            o.problem = "the association with " + describe(peer) + " ended before this file";
            continue;
        }
        const T_ASC_PresentationContextID id =
            scu.findAnyPresentationContextID(infos[n]->sopClass.c_str(), "");
        if (id == 0) {
            o.problem = describe(peer) + " accepts no presentation context for SOP class " +
                        infos[n]->sopClass;
            continue;
        }
        Uint16 status = 0;
        const OFCondition c = scu.sendSTORERequest(id, o.file.c_str(), nullptr, status);
        if (c.bad()) {
            o.problem = std::string("C-STORE to ") + describe(peer) + " failed: " + c.text();
            continue;
        }
        o.status = status;
        o.accepted = acceptedStatus(status);
        if (!o.accepted) {
            o.problem =
                describe(peer) + " answered " + hex(status) + " (" + statusMeaning(status) + ")";
        }
    }
    if (scu.isConnected()) {
        scu.releaseAssociation();
    }
    return outcomes;
}

std::string echo(const DicomPeer& peer, const SendOptions& options) {
    quietDcmtk();
    std::unique_ptr<TlsContext> tls; // outlives scu, whose network uses it
    Scu scu;
    configure(scu, peer, options);
    OFList<OFString> xfers;
    xfers.push_back(UID_LittleEndianImplicitTransferSyntax);
    scu.addPresentationContext(UID_VerificationSOPClass, xfers);
    if (std::string problem = associate(scu, peer, options, tls); !problem.empty()) {
        return problem;
    }
    const OFCondition c = scu.sendECHORequest(0);
    scu.releaseAssociation();
    if (c.bad()) {
        return std::string("C-ECHO to ") + describe(peer) + " failed: " + c.text();
    }
    return {};
}

} // namespace steerseg::net
