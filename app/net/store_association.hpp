#pragma once

// One association of the Storage SCP, on its own thread: negotiation against the configured
// callers, C-ECHO, and each C-STORE filed through the durable write path, within the
// association's byte quota and the store's free-space floor.
#include "net/store_filing.hpp"
#include "net/store_scp.hpp"

struct T_ASC_Association;

namespace steerseg::net {

// Serves `assoc` to its end, then drops and destroys it.
void serveStoreAssociation(T_ASC_Association* assoc, const ScpSettings& settings,
                           StoreShared& shared);

} // namespace steerseg::net
