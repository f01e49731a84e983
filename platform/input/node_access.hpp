#pragma once

// Why a device node could not be opened, in words an installer can act on: the console's
// devices are reached through group `steerseg`, which packaging's udev rule
// (/lib/udev/rules.d/70-steerseg.rules) gives to the nodes, so a denied open is either the
// rule missing (the node has another group) or the user not in the group.
#include <string>
#include <vector>

namespace steerseg::platform::input {

inline constexpr const char* kDeviceGroup = "steerseg";
inline constexpr const char* kUdevRule = "/lib/udev/rules.d/70-steerseg.rules";

// "<node>: <what> failed: <strerror>" and, for EACCES/EPERM, what is missing: the group
// `wantedGroup` itself, the udev rule (the node belongs to another group), or the membership.
std::string nodeOpenProblem(const std::string& node, const std::string& what, int err,
                            const std::string& wantedGroup = kDeviceGroup);

// The sorted nodes in `dir` whose names start with `prefix` ("/dev/input", "event").
std::vector<std::string> listNodes(const std::string& dir, const std::string& prefix);

} // namespace steerseg::platform::input
