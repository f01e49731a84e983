#include "cli/self_test_checks.hpp"

#include "platform/input/node_access.hpp"

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <fcntl.h>
#include <map>
#include <sstream>
#include <unistd.h>

namespace steerseg::cli {

namespace {

std::string systemError(int error) {
    return std::strerror(error);
}

std::string absoluteText(const std::filesystem::path& p) {
    std::error_code ec;
    const std::filesystem::path a = std::filesystem::absolute(p, ec);
    return (ec ? p : a).lexically_normal().string();
}

const char* levelWord(CheckLevel level) {
    switch (level) {
    case CheckLevel::Ok:
        return "ok  ";
    case CheckLevel::Warn:
        return "warn";
    case CheckLevel::Fail:
        return "FAIL";
    }
    return "?";
}

} // namespace

CheckResult checkConfig(const config::LoadedConfig& loaded) {
    CheckResult r{"config", CheckLevel::Ok, "", {}};
    std::string files;
    for (const auto& f : loaded.applied) {
        files += (files.empty() ? "" : ", ") + f.string();
    }
    if (loaded.problems.empty()) {
        r.detail = "built-in defaults" + (files.empty() ? std::string() : " < " + files);
        return r;
    }
    r.level = CheckLevel::Fail;
    r.detail = std::to_string(loaded.problems.size()) +
               " problem(s); a file with a problem is not applied (applied: " +
               (files.empty() ? std::string("defaults only") : files) + ")";
    for (const config::ConfigProblem& p : loaded.problems) {
        r.problems.push_back(config::describe(p));
    }
    return r;
}

CheckResult checkWritableFolder(const std::string& name, const std::filesystem::path& folder) {
    const std::string where = absoluteText(folder);
    std::error_code ec;
    std::filesystem::create_directories(folder, ec);
    if (ec) {
        return {name, CheckLevel::Fail, where + ": cannot create (" + ec.message() + ")", {}};
    }
    // A real file, not access(2): root passes access() on any folder, a read-only mount
    // included, and only a write shows a full disk.
    const std::filesystem::path probe =
        folder / (".steerseg-self-test-" + std::to_string(::getpid()));
    const int fd = ::open(probe.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0600);
    if (fd < 0) {
        return {name,
                CheckLevel::Fail,
                where + ": cannot create a file (" + systemError(errno) + ")",
                {}};
    }
    const char byte = 's';
    const bool written = ::write(fd, &byte, 1) == 1 && ::fsync(fd) == 0;
    const int writeError = errno;
    ::close(fd);
    const bool removed = ::unlink(probe.c_str()) == 0;
    if (!written) {
        return {name,
                CheckLevel::Fail,
                where + ": cannot write a file (" + systemError(writeError) + ")",
                {}};
    }
    if (!removed) {
        return {name,
                CheckLevel::Fail,
                where + ": cannot remove a file (" + systemError(errno) + ")",
                {}};
    }
    return {name, CheckLevel::Ok, where + " writable", {}};
}

CheckResult checkAuditLog(const std::filesystem::path& path) {
    const std::string where = absoluteText(path);
    std::error_code ec;
    if (!std::filesystem::exists(path, ec)) {
        // Not created here: a file made by a self-test run as root would be root's, and the
        // service could not append to it. The folder's check shows a new file can be made.
        return {"audit log", CheckLevel::Ok, where + " not there yet (the kiosk creates it)", {}};
    }
    const int fd = ::open(path.c_str(), O_WRONLY | O_APPEND | O_CLOEXEC);
    if (fd < 0) {
        const int error = errno;
        std::string why = systemError(error);
        if (error == EISDIR) {
            why = "a folder of that name is in the way";
        } else if (error == EACCES || error == EPERM) {
            why = "this user may not append to it (permission denied)";
        }
        return {"audit log", CheckLevel::Fail, where + ": cannot append (" + why + ")", {}};
    }
    ::close(fd);
    return {"audit log", CheckLevel::Ok, where + " opens for append", {}};
}

std::vector<ControllerNode> findControllerNodes(const std::filesystem::path& devRoot) {
    std::vector<ControllerNode> nodes;
    const auto scan = [&](const std::filesystem::path& dir, const std::string& prefix,
                          const std::string& kind) {
        for (const std::string& node : platform::input::listNodes(dir.string(), prefix)) {
            nodes.push_back({kind, node, ::access(node.c_str(), R_OK | W_OK) == 0});
        }
    };
    scan(devRoot, "hidraw", "hidraw");
    scan(devRoot / "input", "event", "input event");
    scan(devRoot, "gpiochip", "gpiochip");
    std::sort(nodes.begin(), nodes.end(),
              [](const ControllerNode& a, const ControllerNode& b) { return a.node < b.node; });
    return nodes;
}

CheckResult checkControllers(const std::vector<ControllerNode>& nodes) {
    CheckResult r{"controllers", CheckLevel::Ok, "", {}};
    if (nodes.empty()) {
        r.level = CheckLevel::Warn;
        r.detail = "no hidraw, input event or gpiochip node: knobs, pedal and touch are absent "
                   "(keys and a script still work)";
        return r;
    }
    // In the order kinds first appear: nodes come sorted by path.
    std::vector<std::string> kinds;
    std::map<std::string, std::pair<int, int>> counts; // kind -> (nodes, accessible)
    for (const ControllerNode& n : nodes) {
        if (counts.find(n.kind) == counts.end()) {
            kinds.push_back(n.kind);
        }
        auto& [all, open] = counts[n.kind];
        ++all;
        open += n.accessible ? 1 : 0;
        if (!n.accessible) {
            r.problems.push_back(n.node.string() +
                                 ": not open to this user (not a supported controller, or the "
                                 "udev rule / group membership is missing)");
        }
    }
    for (const std::string& k : kinds) {
        const auto [all, open] = counts[k];
        r.detail += (r.detail.empty() ? "" : ", ") + std::to_string(all) + " " + k + " (" +
                    std::to_string(open) + " open to this user)";
    }
    return r;
}

std::optional<CheckResult> checkUser(bool root) {
    if (!root) {
        return std::nullopt;
    }
    return CheckResult{"user",
                       CheckLevel::Warn,
                       "running as root: the folder and device checks say what root may do, not "
                       "the service user (sudo -u steerseg steerseg --self-test)",
                       {}};
}

std::string formatReport(const std::vector<CheckResult>& results) {
    std::ostringstream out;
    out << "steerseg self-test\n";
    int failed = 0;
    int warned = 0;
    for (const CheckResult& r : results) {
        out << "  " << levelWord(r.level) << "  " << r.name << ": " << r.detail << '\n';
        for (const std::string& p : r.problems) {
            out << "          " << p << '\n';
        }
        failed += r.level == CheckLevel::Fail ? 1 : 0;
        warned += r.level == CheckLevel::Warn ? 1 : 0;
    }
    if (failed > 0) {
        out << "self-test: FAILED, " << failed << " required check(s) failed\n";
    } else {
        out << "self-test: passed"
            << (warned > 0 ? " with " + std::to_string(warned) + " warning(s)" : "") << '\n';
    }
    return out.str();
}

bool anyFailed(const std::vector<CheckResult>& results) {
    return std::any_of(results.begin(), results.end(),
                       [](const CheckResult& r) { return r.level == CheckLevel::Fail; });
}

} // namespace steerseg::cli
