#pragma once

// Permission errors as a user meets them. Root passes every permission check, and CI runs as
// root, so a test of "not writable" or "no access" would have to skip there; instead the check
// runs in a forked child that first drops to an unprivileged user.
#include <functional>
#include <string>
#include <sys/types.h>

namespace steerseg::test {

// nobody: owns nothing a test makes, so only the "other" permission bits apply to it.
constexpr uid_t kUnprivilegedUid = 65534;
constexpr gid_t kUnprivilegedGid = 65534;

// Runs `fn` as an unprivileged user and returns what it returned: in this process when it is
// not root, else in a child that drops every group and takes nobody's ids first. Throws
// std::runtime_error when the child cannot drop them or dies.
std::string runUnprivileged(const std::function<std::string()>& fn);

} // namespace steerseg::test
