#pragma once

// The running kiosk (kiosk_app.hpp's runKiosk drives it): one class, its frame as named passes,
// the passes in files by concern: the loop and the workflow's side (kiosk_app.cpp), input from
// the display, scripts and devices (kiosk_input.cpp), the screen and a script's frames
// (kiosk_screen.cpp). Private to the kiosk library.
#include "config/kiosk_config.hpp"
#include "engine/session_engine.hpp"
#include "input/input_hub.hpp"
#include "input/key_bindings.hpp"
#include "kiosk/frame_stats.hpp"
#include "kiosk/iteration_budget.hpp"
#include "kiosk/kiosk_dicom_node.hpp"
#include "kiosk/kiosk_options.hpp"
#include "kiosk/kiosk_script_sink.hpp"
#include "kiosk/operator_pacing.hpp"
#include "kiosk/screen_compositor.hpp"
#include "kiosk/service_status.hpp"
#include "kiosk/session_autosave.hpp"
#include "kiosk/view_painter.hpp"
#include "platform/display.hpp"
#include "script/script_player.hpp"
#include "session/numerics_check.hpp"
#include "ui/layout.hpp"
#include "ui/screen_rotation.hpp"
#include "ui/touch_ui.hpp"
#include "workflow/workflow.hpp"

#include <chrono>
#include <cstdint>
#include <filesystem>
#include <iosfwd>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace steerseg::kiosk {

using Clock = std::chrono::steady_clock;

inline constexpr const char* kLogPrefix = "steerseg kiosk: ";

inline double secondsSince(Clock::time_point t) {
    return std::chrono::duration<double>(Clock::now() - t).count();
}

// The running kiosk: everything one frame touches, and the frame as named passes.
class Kiosk {
  public:
    // `liveDevices`: open the configured input devices (not offscreen, where a script's raw
    // records are the only device input). `numerics`: the display's GPU checked against the CPU
    // (session/numerics_check); a speed it failed is off for the session.
    Kiosk(const KioskOptions& options, const config::KioskConfig& cfg,
          std::unique_ptr<script::ScriptPlayer> player, std::unique_ptr<platform::Display> display,
          bool liveDevices, const session::NumericsReport& numerics, std::ostream& err);

    // One frame; false when the kiosk should stop.
    bool step();

    [[nodiscard]] int exitCode() const { return exitCode_; }

    // The journal hears of each outage of the audit log and its end once; the screen shows it
    // all along (Status::auditProblem).
    void reportAudit();

    void finish(std::ostream& out);

  private:
    // The start-up check's verdict in the audit log, and each speed it turned off in the journal.
    void recordNumerics(const session::NumericsReport& numerics);
    static std::vector<std::string> scanList(const KioskOptions& options);

    [[nodiscard]] ui::Layout layout() const;

    // The display's events and the script's due steps, turned into actions. A script waits
    // while a frame it asked for is still being refined, so the file shows the complete
    // picture of the moment the script meant. Returns whether any input came.
    bool pollInput();

    static input::InputHubLimits hubLimits();

    void replayRecording(const std::filesystem::path& path);

    void applyActions();

    // A piece of the speed view's classify speed ahead of the front (a tenth of the frame while
    // evolving, half when not), then the frame's iterations: both are the solver's time.
    void stepSolver();

    // A snapshot when the workflow moved or every interval while evolving (written off this
    // thread), and a resume's last step once its scan is in.
    // The offer of an unfinished session is a prompt over the panel until it is answered.
    void autosave();

    // The views into the logical screen, then the panel on top; the panel's buttons act on the
    // next frame. Not composed when nothing on it changed (a refinement tile drawn off screen,
    // no input; OperatorPacing::screenDue): the panel and the views are not redrawn per tile.
    void drawScreen(bool hadInput);

    void present(Clock::time_point frameStart);

    // Once every view is complete (or can't be while the surface moves), the logical screen.
    void saveFrames();

    std::optional<std::string> stopReason();

    // Nothing moving and no display pacing the loop: do not spin a core.
    void idle(bool hadInput);

    const KioskOptions& options_;
    const config::KioskConfig& cfg_;
    std::ostream& err_;
    std::unique_ptr<script::ScriptPlayer> player_;
    // The display owns the GL context: declared before everything that holds GL objects, so it
    // goes after them.
    std::unique_ptr<platform::Display> display_;
    const platform::DisplayInfo& info_;
    double dpi_;
    glm::ivec2 physical_;
    ui::ScreenRotation rotation_;
    ScreenCompositor screen_;
    engine::SessionEngine engine_;
    SessionAutosave autosave_; // before the audit log: a resume reads it before it reopens
    workflow::AuditLog audit_;
    workflow::Workflow flow_;
    ui::TouchUi touch_;
    input::KeyBindings keys_;
    input::InputHub hub_;
    IterationBudget budget_;
    OperatorPacing pacing_;
    ViewPainter painter_;
    FrameStats stats_;
    KioskScriptSink sink_;
    ServiceStatus service_;
    double frameBudget_;
    Clock::time_point start_;

    std::vector<model::Action> actions_;
    std::vector<platform::InputEvent> events_;
    std::vector<std::filesystem::path> pendingFrames_;
    ui::ScreenState screenState_;
    workflow::Status shown_; // the workflow's status with the controllers, for the panel
    std::uint64_t shownScan_ = 0;
    std::string lastMessage_;
    double now_ = 0.0;
    bool evolving_ = false;
    double solverSeconds_ = 0.0;
    double panelSeconds_ = 0.0; // the panel, composition and present: an average over frames
    bool composed_ = false;     // this frame composed and presents the screen
    model::State composedState_ = model::State::NoScan;
    Clock::time_point panelStart_{};
    double lastFrameSeconds_ = 0.0;
    double inputSince_ = -1.0; // the poll that brought the oldest input not yet on screen
    // When the script asked for the pending frames.
    double framesAskedAt_ = 0.0;
    int exitCode_ = 0;
    DicomNode node_{cfg_.dicom}; // last: its threads stop first
};

} // namespace steerseg::kiosk
