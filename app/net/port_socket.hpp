#pragma once

// The node's port as a socket: every IPv4 address, address reuse on, close-on-exec. The
// Storage SCP listens on it (association_pool); the self-test binds it once to see that it can.
#include <string>

namespace steerseg::net {

// A bound socket (`flags`: SOCK_NONBLOCK or 0), or -1 with the system's reason in `problem`.
int bindPort(int port, int flags, std::string& problem);

} // namespace steerseg::net
