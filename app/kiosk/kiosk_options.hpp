#pragma once

#include <filesystem>
#include <optional>
#include <string>

namespace steerseg::kiosk {

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
};

} // namespace steerseg::kiosk
