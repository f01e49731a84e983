#pragma once

namespace steerseg::net {

// dcmnet logs every refused connection and dropped association on stderr itself; the node
// reports them in its own one-line words instead, so DCMTK's loggers keep only fatal errors.
void quietDcmtk();

} // namespace steerseg::net
