// dcmnet's DcmSCU does the association (net/scu_association); this file chooses the presentation
// contexts from the files' own SOP classes and transfer syntaxes and turns every condition into one
// line.
#include "net/store_scu.hpp"

#include "net/scu_association.hpp"

#include <cstdio>
#include <dcmtk/config/osconfig.h> // must come first among DCMTK's headers
#include <dcmtk/dcmdata/dcdeftag.h>
#include <dcmtk/dcmdata/dcfilefo.h>
#include <dcmtk/dcmdata/dcmetinf.h>
#include <dcmtk/dcmdata/dcuid.h>
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
    PeerScu scu(peer, options);
    // A peer that does not take a compressed syntax gets the object decompressed instead.
    scu.setDatasetConversionMode(OFTrue);
    for (const auto& [sopClass, xfer] : contexts) {
        scu.addPresentationContext(sopClass.c_str(), transferSyntaxes(xfer));
    }
    if (const std::string problem = scu.associate(); !problem.empty()) {
        for (std::size_t n = 0; n < outcomes.size(); ++n) {
            if (infos[n]) {
                outcomes[n].problem = problem;
            }
        }
        return outcomes;
    }
    bool answering = true; // a peer gone silent is aborted, not waited for to release
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
            answering = false;
            continue;
        }
        o.status = status;
        o.accepted = acceptedStatus(status);
        if (!o.accepted) {
            o.problem = statusProblem(peer, status);
        }
    }
    scu.finish(answering);
    return outcomes;
}

std::string echo(const DicomPeer& peer, const SendOptions& options) {
    PeerScu scu(peer, options);
    OFList<OFString> xfers;
    xfers.push_back(UID_LittleEndianImplicitTransferSyntax);
    scu.addPresentationContext(UID_VerificationSOPClass, xfers);
    if (std::string problem = scu.associate(); !problem.empty()) {
        return problem;
    }
    const OFCondition c = scu.sendECHORequest(0);
    scu.finish(c.good());
    if (c.bad()) {
        return std::string("C-ECHO to ") + describe(peer) + " failed: " + c.text();
    }
    return {};
}

} // namespace steerseg::net
