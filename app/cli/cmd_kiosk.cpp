#include "cli/args.hpp"
#include "cli/commands.hpp"
#include "kiosk/kiosk_app.hpp"
#include "scan/scan_reader.hpp"

#include <cstdio>
#include <iostream>
#include <tuple>
#include <unistd.h>

namespace steerseg::cli {

int runKiosk(std::span<const std::string> words) {
    const Args args(
        words, {"platform", "config", "script", "scan", "frames", "size", "max-seconds", "stats"},
        {"allow-root", "resume", "no-resume"});
    // An appliance program that a mistake could run as root (cage does the same): it needs the
    // video and input groups, not root.
    if (::geteuid() == 0 && !args.flag("allow-root")) {
        throw UsageError("refusing to run as root: run the kiosk as its own user in the video "
                         "and input groups (--allow-root overrides, for containers)");
    }
    // Under journald stdout is a pipe, block-buffered by default: a kill -9 or a watchdog abort
    // would take the start-up lines and the frame statistics that say how far the kiosk got.
    std::setvbuf(stdout, nullptr, _IOLBF, 0);
    kiosk::KioskOptions o;
    o.platform = args.value("platform").value_or("");
    if (!o.platform.empty() && o.platform != "auto" && o.platform != "kms" &&
        o.platform != "window" && o.platform != "offscreen") {
        throw UsageError("--platform: expected auto, kms, window or offscreen, got '" + o.platform +
                         "'");
    }
    if (o.platform == "auto") {
        o.platform.clear();
    }
    if (const auto c = args.value("config")) {
        o.config = *c;
    }
    if (const auto s = args.value("script")) {
        o.script = *s;
    }
    o.scan = args.value("scan").value_or("");
    if (const auto f = args.value("frames")) {
        o.frames = *f;
    }
    if (const auto s = args.value("size")) {
        // The panel needs room for its touch targets; the GPU's framebuffers top out at 16384.
        std::tie(o.width, o.height) = parseSize(*s, "--size", 64, 16384);
    }
    if (const auto m = args.number("max-seconds")) {
        if (!(*m > 0.0)) {
            throw UsageError("--max-seconds: must be positive");
        }
        o.maxSeconds = *m;
    }
    if (const auto s = args.value("stats")) {
        o.stats = *s;
    }
    if (args.flag("resume") && args.flag("no-resume")) {
        throw UsageError("--resume and --no-resume: give one");
    }
    if (args.flag("resume")) {
        o.resume = kiosk::ResumeChoice::Yes;
    } else if (args.flag("no-resume")) {
        o.resume = kiosk::ResumeChoice::No;
    }
    return kiosk::runKiosk(o, std::cout, std::cerr);
}

} // namespace steerseg::cli
