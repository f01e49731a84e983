#include "kiosk/kiosk_app.hpp"

#include "config/config_loader.hpp"
#include "engine/session_engine.hpp"
#include "exports/image_file.hpp"
#include "files/file_error.hpp"
#include "input/input_backend.hpp"
#include "input/input_hub.hpp"
#include "input/key_bindings.hpp"
#include "kiosk/frame_stats.hpp"
#include "kiosk/iteration_budget.hpp"
#include "kiosk/kiosk_dicom_node.hpp"
#include "kiosk/kiosk_script_sink.hpp"
#include "kiosk/kiosk_startup.hpp"
#include "kiosk/operator_pacing.hpp"
#include "kiosk/screen_compositor.hpp"
#include "kiosk/service_status.hpp"
#include "kiosk/session_autosave.hpp"
#include "kiosk/settings_from_config.hpp"
#include "kiosk/view_painter.hpp"
#include "platform/display_choice.hpp"
#include "platform/input/recording.hpp"
#include "scan/scan_reader.hpp"
#include "script/mask_dice.hpp"
#include "script/script_player.hpp"
#include "ui/layout.hpp"
#include "ui/screen_rotation.hpp"
#include "ui/touch_ui.hpp"
#include "workflow/workflow.hpp"

#include <chrono>
#include <optional>
#include <ostream>
#include <thread>
#include <utility>

namespace steerseg::kiosk {

namespace {

using Clock = std::chrono::steady_clock;

constexpr const char* kLogPrefix = "steerseg kiosk: ";

double secondsSince(Clock::time_point t) {
    return std::chrono::duration<double>(Clock::now() - t).count();
}

// The running kiosk: everything one frame touches, and the frame as named passes.
class Kiosk {
  public:
    // `liveDevices`: open the configured input devices (not offscreen, where a script's raw
    // records are the only device input).
    Kiosk(const KioskOptions& options, const config::KioskConfig& cfg,
          std::unique_ptr<script::ScriptPlayer> player, std::unique_ptr<platform::Display> display,
          bool liveDevices, std::ostream& err)
        : options_(options), cfg_(cfg), err_(err), player_(std::move(player)),
          display_(std::move(display)), info_(display_->info()),
          dpi_(cfg.display.dpi > 0.0 ? cfg.display.dpi : info_.dpi),
          physical_(info_.width, info_.height),
          rotation_(cfg.display.rotation, physical_.x, physical_.y),
          screen_(physical_, cfg.display.rotation),
          engine_(engine::consoleSolverOptions(),
                  {cfg.speed.smoothIterations, cfg.speed.conductanceFactor, cfg.speed.kappaFactor}),
          autosave_(cfg.autosave, cfg.audit.path, options.resume, err), audit_(cfg.audit.path),
          flow_(engine_, workflowSettings(cfg), &audit_),
          touch_({dpi_, cfg.ui.touchTargetMm, cfg.ui.fontScale, cfg.probe.radiusMm,
                  static_cast<double>(cfg.ui.longPressMs), "", scanList(options)}),
          keys_(cfg.bindings.keys),
          hub_(input::deviceSpecs(cfg.input.devices),
               input::ControlBindings(cfg.bindings.knobs, cfg.bindings.buttons),
               liveDevices ? input::liveInputBackend(err, kLogPrefix) : input::replayInputBackend(),
               liveDevices, err, hubLimits()),
          budget_(cfg.frame.solverShare, cfg.frame.budgetMs * 1e-3, cfg.frame.minIterations,
                  cfg.frame.maxIterations),
          painter_(cfg.frame.interactiveScale), frameBudget_(cfg.frame.budgetMs * 1e-3),
          start_(Clock::now()) {
        screenState_.layout = layout();
        if (const auto note = audit_.takeRepairNote()) {
            err_ << kLogPrefix << *note << '\n';
        }
        if (!options.scan.empty() && !player_ && !autosave_.resuming()) {
            actions_.emplace_back(model::LoadScan{options.scan});
        }
    }

    // One frame; false when the kiosk should stop.
    bool step() {
        const Clock::time_point frameStart = Clock::now();
        now_ = secondsSince(start_);
        const bool hadInput = pollInput();
        if (hadInput) {
            pacing_.input(now_);
        }
        applyActions();
        node_.frame(flow_.status(), audit_, err_);
        reportAudit();
        stepSolver();
        autosave();
        drawScreen(hadInput);
        present(frameStart);
        service_.framePresented(flow_.status());
        saveFrames();
        if (stopReason()) {
            return false;
        }
        idle(hadInput);
        return true;
    }

    [[nodiscard]] int exitCode() const { return exitCode_; }

    // The journal hears of each outage of the audit log and its end once; the screen shows it
    // all along (Status::auditProblem).
    void reportAudit() {
        if (const auto error = audit_.takeError()) {
            err_ << kLogPrefix << *error << '\n';
        }
    }

    void finish(std::ostream& out) {
        service_.stopping();
        autosave_.finish(flow_, engine_);
        node_.finish(audit_, err_);
        reportAudit();
        out << stats_.summary() << '\n';
        if (options_.stats) {
            const ui::Layout l = layout();
            stats_.viewSizes(
                {{l.view3d.w, l.view3d.h}, {l.slice1.w, l.slice1.h}, {l.slice2.w, l.slice2.h}});
            stats_.write(*options_.stats, info_.description);
        }
        if (!audit_.ok()) {
            // The records held for the log end with the process: a session without its audit
            // trail does not end as a success (exit 4, as for any output not written).
            throw files::WriteError(audit_.path(), std::to_string(audit_.held()) +
                                                       " audit records could not be written (" +
                                                       audit_.problem() + ")");
        }
    }

  private:
    static std::vector<std::string> scanList(const KioskOptions& options) {
        std::vector<std::string> scans{scan::kBuiltinSample};
        if (!options.scan.empty()) {
            scans.push_back(options.scan);
        }
        return scans;
    }

    [[nodiscard]] ui::Layout layout() const {
        return ui::computeLayout(screen_.size().x, screen_.size().y, dpi_, cfg_.ui.touchTargetMm);
    }

    // The display's events and the script's due steps, turned into actions. A script waits
    // while a frame it asked for is still being refined, so the file shows the complete
    // picture of the moment the script meant. Returns whether any input came.
    bool pollInput() {
        events_.clear();
        display_->pollEvents(events_);
        if (player_ && pendingFrames_.empty()) {
            player_->poll(now_, node_.shown(flow_.status()), sink_);
            for (auto& a : sink_.actions) {
                actions_.push_back(std::move(a));
            }
            // A script's device-level events stand for the display's: physical pixels.
            for (auto& e : sink_.events) {
                events_.push_back(std::move(e));
            }
            if (pendingFrames_.empty() && !sink_.frames.empty()) {
                framesAskedAt_ = now_;
            }
            for (auto& f : sink_.frames) {
                pendingFrames_.push_back(std::move(f));
            }
            // A script's raw records are a device's input: they count for the latency.
            const std::size_t beforeRaw = actions_.size();
            for (const auto& r : sink_.raws) {
                hub_.inject(r, actions_);
            }
            if (actions_.size() > beforeRaw && inputSince_ < 0.0) {
                inputSince_ = now_;
            }
            for (const auto& path : sink_.recordings) {
                replayRecording(path);
            }
            sink_.raws.clear();
            sink_.recordings.clear();
            sink_.actions.clear();
            sink_.events.clear();
            sink_.frames.clear();
            if (const auto answer = std::exchange(sink_.resumeAnswer, std::nullopt)) {
                autosave_.answer(*answer);
            }
        }
        if (!events_.empty() && inputSince_ < 0.0) {
            inputSince_ = now_;
        }
        // Knobs, rings, buttons and pedals (and a replay's records) through their decoders.
        const std::size_t beforeDevices = actions_.size();
        hub_.poll(now_, actions_);
        if (actions_.size() > beforeDevices && inputSince_ < 0.0) {
            inputSince_ = now_;
        }
        for (const platform::InputEvent& raw : events_) {
            if (raw.kind == platform::InputEvent::Kind::Quit) {
                StopSignals::requestStop();
                break;
            }
            if (const auto bound = keys_.actionFor(raw)) {
                actions_.push_back(*bound);
                continue;
            }
            touch_.feed(rotation_.toLogical(raw), screenState_, flow_.status(), actions_);
        }
        return !events_.empty() || !actions_.empty() || hub_.busy();
    }

    static input::InputHubLimits hubLimits() {
        input::InputHubLimits limits;
        limits.logPrefix = kLogPrefix;
        return limits;
    }

    void replayRecording(const std::filesystem::path& path) {
        platform::input::Recording recording = platform::input::readRecording(path.string());
        constexpr std::size_t kShown = 5; // a bad file's first lines say enough
        for (std::size_t i = 0; i < recording.problems.size() && i < kShown; ++i) {
            err_ << kLogPrefix << "replay: " << recording.problems[i] << '\n';
        }
        if (recording.problems.size() > kShown) {
            err_ << kLogPrefix << "replay: " << recording.problems.size() - kShown
                 << " more problems in " << path.string() << '\n';
        }
        hub_.replay(std::move(recording.records), now_);
    }

    void applyActions() {
        for (const model::Action& a : actions_) {
            const workflow::Workflow::Outcome o = flow_.handle(a);
            if (!o.accepted) {
                err_ << "steerseg kiosk: " << model::actionName(a) << " refused: " << o.reason
                     << '\n';
            }
        }
        actions_.clear();
        flow_.update();
        hub_.setIndicator(input::indicatorFor(flow_.state()));
        // What the panel's message line says goes to the log too: a headless run has no panel.
        if (const std::string& message = flow_.status().message; message != lastMessage_) {
            lastMessage_ = message;
            if (!message.empty()) {
                err_ << "steerseg kiosk: " << message << '\n';
            }
        }
    }

    // A piece of the speed view's classify speed ahead of the front (a tenth of the frame while
    // evolving, half when not), then the frame's iterations: both are the solver's time.
    void stepSolver() {
        solverSeconds_ = 0.0;
        evolving_ = flow_.state() == model::State::Evolving;
        const Clock::time_point fill = Clock::now();
        if (engine_.fillSpeedAhead(frameBudget_ * (evolving_ ? 0.1 : 0.5))) {
            solverSeconds_ = secondsSince(fill);
        }
        if (!evolving_) {
            return;
        }
        // Nobody touching anything: the solver takes a slice of the machine between previews.
        const double slice = pacing_.solverSlice(now_);
        if (const int n = slice > 0.0 ? budget_.forSlice(slice) : budget_.next(lastFrameSeconds_);
            n > 0) {
            const Clock::time_point t = Clock::now();
            const model::StepResult r = flow_.evolve(n);
            const double evolved = secondsSince(t);
            solverSeconds_ += evolved;
            budget_.record(r.iterations, evolved);
            stats_.iterations(r.iterations, evolved);
        }
    }

    // A snapshot when the workflow moved or every interval while evolving (written off this
    // thread), and a resume's last step once its scan is in.
    // The offer of an unfinished session is a prompt over the panel until it is answered.
    void autosave() {
        if (const auto choice = touch_.takePromptChoice()) {
            autosave_.answer(*choice == 0);
        }
        autosave_.frame(flow_, engine_, actions_);
        touch_.setPrompt(autosave_.offering()
                             ? std::optional<ui::Prompt>(ui::Prompt{"Resume the last session?",
                                                                    autosave_.offerText(),
                                                                    {"Resume", "Discard"}})
                             : std::nullopt);
    }

    // The views into the logical screen, then the panel on top; the panel's buttons act on the
    // next frame. Not composed when nothing on it changed (a refinement tile drawn off screen,
    // no input; OperatorPacing::screenDue): the panel and the views are not redrawn per tile.
    void drawScreen(bool hadInput) {
        bool changed = hadInput || evolving_ || touch_.pressing() || !pendingFrames_.empty() ||
                       engine_.session() == nullptr || flow_.state() != composedState_;
        if (session::Session* session = engine_.session()) {
            if (engine_.scansAttached() != shownScan_) {
                painter_.reset();
                shownScan_ = engine_.scansAttached();
            }
            // The views get what the solver and the panel leave of the frame.
            const double left =
                std::max(frameBudget_ - solverSeconds_ - panelSeconds_, frameBudget_ * 0.25);
            changed = painter_.draw(*session, flow_.status(), engine_.levelSetVersion(),
                                    engine_.speedVersion(), layout(), left,
                                    pacing_.refineSeconds(now_, left, !pendingFrames_.empty())) ||
                      changed;
            const auto [pixels, seconds] = painter_.takeDrawn();
            stats_.drawn(pixels, seconds);
        }
        composed_ = pacing_.screenDue(now_, changed);
        if (!composed_) {
            return;
        }
        composedState_ = flow_.state();
        screen_.begin({0.08F, 0.08F, 0.09F});
        screenState_ = {layout(), {}, {}};
        if (session::Session* session = engine_.session()) {
            screenState_ = painter_.compose(*session, screenState_.layout, screen_);
        }
        panelStart_ = Clock::now();
        glBindFramebuffer(GL_FRAMEBUFFER, screen_.framebuffer());
        // The panel lists the controllers and the DICOM node beside what the workflow publishes.
        shown_ = flow_.status();
        shown_.devices = hub_.links();
        node_.show(shown_);
        for (auto& a : touch_.drawFrame(screen_.size(), now_, screenState_, shown_)) {
            actions_.push_back(std::move(a));
        }
    }

    void present(Clock::time_point frameStart) {
        if (composed_) {
            screen_.present(display_->framebuffer(), physical_);
            glFinish(); // the panel's and the present's cost, for the next frame's split
            panelSeconds_ = 0.8 * panelSeconds_ + 0.2 * secondsSince(panelStart_);
            display_->present();
        }
        lastFrameSeconds_ = secondsSince(frameStart);
        if (engine_.session() != nullptr) { // frames showing a scan: not the wait for a load
            stats_.frame(lastFrameSeconds_, evolving_);
        }
        // Input to screen: from the poll that brought an event to the present of the frame that
        // drew all it led to. A panel button acts, and is drawn, a frame later: its actions
        // are still queued here. A script's operator-level actions are no device's input.
        if (inputSince_ >= 0.0 && actions_.empty()) {
            stats_.latency(secondsSince(start_) - inputSince_);
            inputSince_ = -1.0;
        }
    }

    // Once every view is complete (or can't be while the surface moves), the logical screen.
    void saveFrames() {
        if (pendingFrames_.empty() ||
            !(painter_.settled() || evolving_ || engine_.session() == nullptr)) {
            return;
        }
        const RgbaImage picture = screen_.capture();
        for (const auto& path : pendingFrames_) {
            exports::writeImage(path, picture);
        }
        pendingFrames_.clear();
        stats_.frameWait(secondsSince(start_) - framesAskedAt_);
    }

    std::optional<std::string> stopReason() {
        if (StopSignals::stopRequested()) {
            return "signal or quit";
        }
        if (flow_.quitRequested()) {
            return "quit";
        }
        if (player_ && (player_->finished() || player_->failed()) && pendingFrames_.empty()) {
            if (player_->failed()) {
                err_ << "steerseg kiosk: " << player_->failure() << '\n';
                exitCode_ = 1;
            }
            return "script ended";
        }
        if (options_.maxSeconds > 0.0 && secondsSince(start_) > options_.maxSeconds) {
            err_ << "steerseg kiosk: stopped after " << options_.maxSeconds
                 << " s (--max-seconds)\n";
            exitCode_ = 1;
            return "time limit";
        }
        return std::nullopt;
    }

    // Nothing moving and no display pacing the loop: do not spin a core.
    void idle(bool hadInput) {
        if (info_.refreshHz <= 0.0 && !evolving_ &&
            (painter_.settled() || engine_.session() == nullptr) && !hadInput &&
            pendingFrames_.empty()) {
            std::this_thread::sleep_for(std::chrono::milliseconds(5));
        }
    }

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

} // namespace

int runKiosk(const KioskOptions& options, std::ostream& out, std::ostream& err) {
    const config::LoadedConfig loaded = readConfig(options, err);
    const config::KioskConfig& cfg = loaded.config;
    std::unique_ptr<script::ScriptPlayer> player = makePlayer(options); // before a window opens
    prepareOutputs(options);
    const std::string configured = options.platform.empty()
                                       ? std::string(config::platformName(cfg.display.platform))
                                       : options.platform;
    const std::string platformName =
        platform::defaultPlatform(configured, platform::DisplayEnvironment::current());
    platform::DisplayOptions displayOpts = displayOptions(cfg.display);
    if (options.width > 0 && options.height > 0) {
        displayOpts.width = options.width;
        displayOpts.height = options.height;
    }
    std::unique_ptr<platform::Display> display = openDisplay(platformName, displayOpts);
    out << "steerseg kiosk: " << display->info().description << '\n';
    StopSignals signals;
    Kiosk kiosk(options, cfg, std::move(player), std::move(display), platformName != "offscreen",
                err);
    while (kiosk.step()) {
    }
    kiosk.finish(out);
    return kiosk.exitCode();
}

} // namespace steerseg::kiosk
