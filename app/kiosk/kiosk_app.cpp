#include "kiosk/kiosk_app.hpp"

#include "config/config_loader.hpp"
#include "files/file_error.hpp"
#include "input/input_backend.hpp"
#include "kiosk/kiosk.hpp"
#include "kiosk/kiosk_startup.hpp"
#include "kiosk/settings_from_config.hpp"
#include "platform/display_choice.hpp"
#include "scan/scan_reader.hpp"

#include <cmath>
#include <nlohmann/json.hpp>
#include <ostream>
#include <thread>
#include <utility>

namespace steerseg::kiosk {

Kiosk::Kiosk(const KioskOptions& options, const config::KioskConfig& cfg,
             std::unique_ptr<script::ScriptPlayer> player,
             std::unique_ptr<platform::Display> display, bool liveDevices,
             const session::NumericsReport& numerics, std::ostream& err)
    : options_(options), cfg_(cfg), err_(err), player_(std::move(player)),
      display_(std::move(display)), info_(display_->info()),
      dpi_(cfg.display.dpi > 0.0 ? cfg.display.dpi : info_.dpi),
      physical_(info_.width, info_.height),
      rotation_(cfg.display.rotation, physical_.x, physical_.y),
      screen_(physical_, cfg.display.rotation),
      engine_(engine::consoleSolverOptions(),
              {cfg.speed.smoothIterations, cfg.speed.conductanceFactor, cfg.speed.kappaFactor}),
      autosave_(cfg.autosave, cfg.audit.path, options.resume, err), audit_(cfg.audit.path),
      flow_(engine_, workflowSettings(cfg, &numerics), &audit_),
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
    recordNumerics(numerics);
    if (!options.scan.empty() && !player_ && !autosave_.resuming()) {
        actions_.emplace_back(model::LoadScan{options.scan});
    }
}

bool Kiosk::step() {
    const Clock::time_point frameStart = Clock::now();
    now_ = secondsSince(start_);
    const bool hadInput = pollInput();
    if (hadInput) {
        pacing_.input(now_);
    }
    const bool wasEvolving = flow_.state() == model::State::Evolving;
    applyActions();
    if (!wasEvolving && flow_.state() == model::State::Evolving) {
        pacing_.runStarted();
        budget_.restartSlices();
    }
    node_.frame(flow_.status(), audit_, err_);
    reportAudit();
    stepSolver();
    autosave();
    drawScreen(hadInput);
    present(frameStart);
    // After the frame that shows an edit: the older undo copies leave the GPU here, not
    // before it (SessionEngine::snapshot).
    engine_.keepUndoWithinBudget();
    service_.framePresented(flow_.status());
    saveFrames();
    if (stopReason()) {
        return false;
    }
    idle(hadInput);
    return true;
}

void Kiosk::recordNumerics(const session::NumericsReport& numerics) {
    nlohmann::json speeds = nlohmann::json::array();
    for (const session::SpeedNumerics& s : numerics.speeds) {
        // JSON has no infinity: a value that was not a number is the largest difference there is.
        speeds.push_back({{"speed", model::speedKindName(s.kind)},
                          {"passed", s.passed},
                          {"largest_difference", std::isfinite(s.largestDifference)
                                                     ? nlohmann::json(s.largestDifference)
                                                     : nlohmann::json("not a number")},
                          {"detail", s.detail}});
        if (!s.passed) {
            err_ << kLogPrefix << "GPU numerics check: the " << model::speedKindName(s.kind)
                 << " speed is WRONG on this GPU and is off: " << s.detail << '\n';
        }
    }
    audit_.numericsCheck(numerics.allPassed(), speeds, numerics.seconds);
    if (const std::string& alarm = flow_.status().gpuAlarm; !alarm.empty()) {
        err_ << kLogPrefix << alarm << '\n';
    }
}

void Kiosk::reportAudit() {
    if (const auto error = audit_.takeError()) {
        err_ << kLogPrefix << *error << '\n';
    }
}

void Kiosk::finish(std::ostream& out) {
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

std::vector<std::string> Kiosk::scanList(const KioskOptions& options) {
    std::vector<std::string> scans{scan::kBuiltinSample};
    if (!options.scan.empty()) {
        scans.push_back(options.scan);
    }
    return scans;
}

ui::Layout Kiosk::layout() const {
    return ui::computeLayout(screen_.size().x, screen_.size().y, dpi_, cfg_.ui.touchTargetMm);
}

void Kiosk::applyActions() {
    for (const model::Action& a : actions_) {
        const workflow::Workflow::Outcome o = flow_.handle(a);
        if (!o.accepted) {
            err_ << kLogPrefix << model::actionName(a) << " refused: " << o.reason << '\n';
        } else if (std::holds_alternative<model::SearchPacs>(a) ||
                   std::holds_alternative<model::ListPacsSeries>(a) ||
                   std::holds_alternative<model::RetrievePacs>(a) ||
                   std::holds_alternative<model::CancelRetrieve>(a)) {
            // Checked and recorded by the workflow; the network is the node's.
            node_.request(a);
        }
    }
    actions_.clear();
    flow_.update();
    hub_.setIndicator(input::indicatorFor(flow_.state()));
    // What the panel's message line says goes to the log too: a headless run has no panel.
    if (const std::string& message = flow_.status().message; message != lastMessage_) {
        lastMessage_ = message;
        if (!message.empty()) {
            err_ << kLogPrefix << message << '\n';
        }
    }
}

void Kiosk::stepSolver() {
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

void Kiosk::autosave() {
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

std::optional<std::string> Kiosk::stopReason() {
    if (StopSignals::stopRequested()) {
        return "signal or quit";
    }
    if (flow_.quitRequested()) {
        return "quit";
    }
    if (player_ && (player_->finished() || player_->failed()) && pendingFrames_.empty()) {
        if (player_->failed()) {
            err_ << kLogPrefix << player_->failure() << '\n';
            exitCode_ = 1;
        }
        return "script ended";
    }
    if (options_.maxSeconds > 0.0 && secondsSince(start_) > options_.maxSeconds) {
        err_ << kLogPrefix << "stopped after " << options_.maxSeconds << " s (--max-seconds)\n";
        exitCode_ = 1;
        return "time limit";
    }
    return std::nullopt;
}

void Kiosk::idle(bool hadInput) {
    if (info_.refreshHz <= 0.0 && !evolving_ &&
        (painter_.settled() || engine_.session() == nullptr) && !hadInput &&
        pendingFrames_.empty()) {
        std::this_thread::sleep_for(std::chrono::milliseconds(5));
    }
}

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
    out << kLogPrefix << display->info().description << '\n';
    StopSignals signals;
    // Before the first frame, on the display's own context: a speed this GPU computes wrong is
    // off before an operator can choose it.
    const session::NumericsReport numerics = session::checkGpuNumerics();
    Kiosk kiosk(options, cfg, std::move(player), std::move(display), platformName != "offscreen",
                numerics, err);
    while (kiosk.step()) {
    }
    kiosk.finish(out);
    return kiosk.exitCode();
}

} // namespace steerseg::kiosk
