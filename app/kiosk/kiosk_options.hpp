#pragma once

#include <filesystem>
#include <optional>
#include <string>

namespace steerseg::kiosk {

// What to do with an unfinished session's autosave found at start (docs/kiosk.md).
enum class ResumeChoice {
    Ask, // the panel offers Resume / Discard (a script answers with `autosave resume|discard`)
    Yes, // --resume
    No,  // --no-resume: start afresh (the autosaves stay until rotation removes them)
};

// `steerseg kiosk`'s command line.
struct KioskOptions {
    std::string platform;                        // "" = the config's, then auto
    std::optional<std::filesystem::path> config; // --config, over /etc/steerseg/steerseg.toml
    std::optional<std::filesystem::path> script; // a session to replay (docs/scripts.md)
    std::string scan;                            // --scan: loaded at start; $SCAN in scripts
    std::optional<std::filesystem::path> frames; // where `frame` steps and relative paths go
    int width = 0;                               // --size: the offscreen/window size (0 = config)
    int height = 0;
    double maxSeconds = 0.0; // > 0: give up after this long (a script that never ends)
    std::optional<std::filesystem::path> stats; // --stats FILE: frame times and latencies, JSON
    ResumeChoice resume = ResumeChoice::Ask;
};

} // namespace steerseg::kiosk
