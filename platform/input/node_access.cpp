#include "platform/input/node_access.hpp"

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <filesystem>
#include <grp.h>
#include <sys/stat.h>
#include <unistd.h>
#include <vector>

namespace steerseg::platform::input {
namespace {

bool userInGroup(gid_t gid) {
    if (getegid() == gid) {
        return true;
    }
    const int count = getgroups(0, nullptr);
    if (count <= 0) {
        return false;
    }
    std::vector<gid_t> groups(static_cast<std::size_t>(count));
    const int got = getgroups(count, groups.data());
    return got > 0 && std::find(groups.begin(), groups.begin() + got, gid) != groups.begin() + got;
}

std::string groupName(gid_t gid) {
    const struct group* g = getgrgid(gid);
    return g != nullptr ? std::string(g->gr_name) : std::to_string(gid);
}

} // namespace

std::string nodeOpenProblem(const std::string& node, const std::string& what, int err,
                            const std::string& wantedGroup) {
    std::string text = node + ": " + what + " failed: " + std::strerror(err);
    if (err != EACCES && err != EPERM) {
        return text;
    }
    const struct group* wanted = getgrnam(wantedGroup.c_str());
    if (wanted == nullptr) {
        return text + " (group '" + wantedGroup +
               "' does not exist: install the steerseg package or " +
               "create it, and add the kiosk user to it)";
    }
    struct stat st {};
    if (stat(node.c_str(), &st) == 0 && st.st_gid != wanted->gr_gid) {
        return text + " (the node belongs to group '" + groupName(st.st_gid) + "', not '" +
               wantedGroup + "': the udev rule " + kUdevRule + " is missing or did not match)";
    }
    if (!userInGroup(wanted->gr_gid)) {
        return text + " (this user is not in group '" + wantedGroup + "': usermod -aG " +
               wantedGroup + " <user>, then log in again)";
    }
    return text + " (the node's mode denies group '" + wantedGroup + "': check " + kUdevRule + ")";
}

std::vector<std::string> listNodes(const std::string& dir, const std::string& prefix) {
    std::vector<std::string> nodes;
    std::error_code ec;
    for (std::filesystem::directory_iterator it(dir, ec), end; !ec && it != end; it.increment(ec)) {
        const std::string name = it->path().filename().string();
        if (name.rfind(prefix, 0) == 0) {
            nodes.push_back(it->path().string());
        }
    }
    // event10 after event9: by length, then by name.
    std::sort(nodes.begin(), nodes.end(), [](const std::string& a, const std::string& b) {
        return a.size() != b.size() ? a.size() < b.size() : a < b;
    });
    return nodes;
}

} // namespace steerseg::platform::input
