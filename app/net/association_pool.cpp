#include "net/association_pool.hpp"

#include <dcmtk/config/osconfig.h> // must come first among DCMTK's headers
#include <dcmtk/dcmnet/assoc.h>
#include <stdexcept>
#include <system_error>

namespace steerseg::net {

AssociationPool::AssociationPool(int port, int acseTimeoutSeconds, int max)
    : port_(port), acseTimeoutSeconds_(acseTimeoutSeconds), max_(max) {}

AssociationPool::~AssociationPool() {
    reap(true);
    if (network_ != nullptr) {
        ASC_dropNetwork(&network_);
    }
}

void AssociationPool::open(DcmTransportLayer* tls) {
    OFCondition c = ASC_initializeNetwork(NET_ACCEPTOR, port_, acseTimeoutSeconds_, &network_);
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
            it = workers_.erase(it);
        } else {
            ++it;
        }
    }
}

void AssociationPool::serve(const std::atomic<bool>& stop, const Serve& serve, const Busy& busy,
                            const Idle& idle, const Refused& refused) {
    while (!stop) {
        reap(false);
        if (workers_.empty()) {
            idle();
        }
        T_ASC_Association* assoc = nullptr;
        // Waits a second for a connection; the request is then read within the ACSE timeout.
        const OFCondition c =
            ASC_receiveAssociation(network_, &assoc, ASC_DEFAULTMAXPDU, nullptr, nullptr,
                                   secure_ ? OFTrue : OFFalse, DUL_NOBLOCK, 1);
        if (c.bad()) {
            // No connection within the second, a failed TLS handshake, or bytes that are no
            // association request: that connection ends, the node goes on.
            if (c != DUL_NOASSOCIATIONREQUEST) {
                ASC_dropAssociation(assoc);
                if (secure_) {
                    refused(c.text());
                }
            }
            ASC_destroyAssociation(&assoc);
            continue;
        }
        if (workers_.size() >= static_cast<std::size_t>(max_)) {
            T_ASC_RejectParameters reject{ASC_RESULT_REJECTEDTRANSIENT,
                                          ASC_SOURCE_SERVICEPROVIDER_PRESENTATION_RELATED,
                                          ASC_REASON_SP_PRES_LOCALLIMITEXCEEDED};
            ASC_rejectAssociation(assoc, &reject);
            busy(assoc->params->DULparams.callingAPTitle,
                 assoc->params->DULparams.callingPresentationAddress);
            ASC_dropAssociation(assoc);
            ASC_destroyAssociation(&assoc);
            continue;
        }
        Worker& worker = workers_.emplace_back();
        try {
            worker.thread = std::thread([&serve, &worker, assoc] {
                serve(assoc);
                worker.done = true;
            });
        } catch (const std::system_error&) {
            // No thread to be had: as busy as can be.
            workers_.pop_back();
            busy(assoc->params->DULparams.callingAPTitle,
                 assoc->params->DULparams.callingPresentationAddress);
            ASC_abortAssociation(assoc);
            ASC_destroyAssociation(&assoc);
        }
    }
    reap(true);
}

} // namespace steerseg::net
