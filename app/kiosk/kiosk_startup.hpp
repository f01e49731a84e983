#pragma once

// What `steerseg kiosk` sets up before its first frame: the stop signals, the layered config
// (its problems logged), the display of the chosen platform, the script's player.
#include "config/config_loader.hpp"
#include "kiosk/kiosk_options.hpp"
#include "platform/display.hpp"
#include "script/script_player.hpp"

#include <memory>
#include <ostream>
#include <string>

namespace steerseg::kiosk {

// SIGTERM (systemd stopping the unit) and SIGINT end the loop between frames, so the audit log
// and the display are closed properly; the previous handlers come back on exit.
class StopSignals {
  public:
    StopSignals();
    ~StopSignals();
    StopSignals(const StopSignals&) = delete;
    StopSignals& operator=(const StopSignals&) = delete;

    // A signal came (or requestStop was called) since construction.
    [[nodiscard]] static bool stopRequested();
    static void requestStop();

  private:
    void (*term_)(int) = nullptr;
    void (*int_)(int) = nullptr;
};

// The layered config (defaults < /etc < --config); each problem logged as one line on `err`.
config::LoadedConfig readConfig(const KioskOptions& options, std::ostream& err);

// "offscreen", "window" or "kms"; DisplayError naming the failing step.
std::unique_ptr<platform::Display> openDisplay(const std::string& platform,
                                               const platform::DisplayOptions& options);

// Checks the --frames folder (creating it) and the --stats file can be written, throwing
// files::WriteError in one line. Called after the script is read, so that a refused script leaves
// no folder behind, and before the display opens, so that a session does not run for minutes to
// fail at its first frame or its last line on an output it could never write (exit status 4).
void prepareOutputs(const KioskOptions& options);

// The --script's player with SCAN, DATA and OUT set; nullptr without a script.
std::unique_ptr<script::ScriptPlayer> makePlayer(const KioskOptions& options);

} // namespace steerseg::kiosk
