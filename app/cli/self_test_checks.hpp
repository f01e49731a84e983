#pragma once

// The checks of `steerseg --self-test` that need no GL: the layered config, the folders the
// kiosk writes, the controller nodes. cmd_self_test.cpp adds the GL and shader checks and
// prints the report.
#include "config/config_loader.hpp"

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace steerseg::cli {

enum class CheckLevel { Ok, Warn, Fail };

struct CheckResult {
    std::string name;
    CheckLevel level = CheckLevel::Ok;
    std::string detail;                // why, on the check's line
    std::vector<std::string> problems; // further lines under it (each config problem)
};

// The loaded layers: Fail when any layer had a problem (that file was not applied).
CheckResult checkConfig(const config::LoadedConfig& loaded);

// Creates `folder` where missing, then creates, writes and removes a probe file in it: what
// the kiosk will do there, as this user. Fail with the step and the system's reason.
CheckResult checkWritableFolder(const std::string& name, const std::filesystem::path& folder);

// Opens an existing audit log for append as the kiosk does, writing nothing and creating
// nothing: Fail when the service could not (the file not this user's to write, a folder of that
// name, a read-only mount), which the folder's check alone does not show.
CheckResult checkAuditLog(const std::filesystem::path& path);

// Device nodes controllers may sit behind, below `devRoot` (/dev): hidraw*, input/event*,
// gpiochip*, and whether this process may open each for reading and writing.
struct ControllerNode {
    std::string kind; // "hidraw", "input event", "gpiochip"
    std::filesystem::path node;
    bool accessible = false;
};
std::vector<ControllerNode> findControllerNodes(const std::filesystem::path& devRoot);

// Informational: Ok with counts, Warn when no node is there at all. A node this user cannot
// open is named (the udev rule or group is missing), but is no failure: most are keyboards'.
CheckResult checkControllers(const std::vector<ControllerNode>& nodes);

// Warn when run as root: the folder and device checks then say nothing about the service user.
std::optional<CheckResult> checkUser(bool root);

// "  ok    name: detail" lines, problems indented below, and a closing line.
std::string formatReport(const std::vector<CheckResult>& results);
bool anyFailed(const std::vector<CheckResult>& results);

} // namespace steerseg::cli
