#include "kiosk/kiosk_app.hpp"

#include "config/config_loader.hpp"
#include "io/image_file.hpp"
#include "io/scan_reader.hpp"
#include "kiosk/frame_stats.hpp"
#include "kiosk/iteration_budget.hpp"
#include "kiosk/key_bindings.hpp"
#include "kiosk/mask_dice.hpp"
#include "kiosk/screen_compositor.hpp"
#include "kiosk/script_player.hpp"
#include "kiosk/session_engine.hpp"
#include "kiosk/settings_from_config.hpp"
#include "kiosk/view_painter.hpp"
#include "platform/display_choice.hpp"
#include "platform/egl/offscreen_display.hpp"
#include "platform/kms/kms_display.hpp"
#include "platform/window/window_display.hpp"
#include "ui/layout.hpp"
#include "ui/screen_rotation.hpp"
#include "ui/touch_ui.hpp"
#include "workflow/workflow.hpp"

#include <atomic>
#include <chrono>
#include <csignal>
#include <cstdlib>
#include <deque>
#include <ostream>
#include <thread>

namespace steerseg::kiosk {

namespace {

using Clock = std::chrono::steady_clock;

std::atomic<bool> g_stop{false};

extern "C" void onStopSignal(int /*signal*/) {
    g_stop = true;
}

// SIGTERM (systemd stopping the unit) and SIGINT end the loop between frames, so the audit log
// and the display are closed properly; the previous handlers come back on exit.
class StopSignals {
  public:
    StopSignals() {
        g_stop = false;
        term_ = std::signal(SIGTERM, onStopSignal);
        int_ = std::signal(SIGINT, onStopSignal);
    }
    ~StopSignals() {
        std::signal(SIGTERM, term_);
        std::signal(SIGINT, int_);
    }
    StopSignals(const StopSignals&) = delete;
    StopSignals& operator=(const StopSignals&) = delete;

  private:
    void (*term_)(int) = SIG_DFL;
    void (*int_)(int) = SIG_DFL;
};

double secondsSince(Clock::time_point t) {
    return std::chrono::duration<double>(Clock::now() - t).count();
}

config::LoadedConfig readConfig(const KioskOptions& options, std::ostream& err) {
    const config::BindingCheck check = [](std::string_view action) {
        return workflow::bindingAction(action, 1.0).has_value();
    };
    config::LoadedConfig loaded =
        config::loadConfig(config::kioskConfigSources(options.config), check);
    for (const config::ConfigProblem& p : loaded.problems) {
        err << "steerseg kiosk: config: " << config::describe(p) << '\n';
    }
    return loaded;
}

std::unique_ptr<platform::Display> openDisplay(const std::string& platform,
                                               const platform::DisplayOptions& options) {
    if (platform == "offscreen") {
        return platform::openOffscreenDisplay(options);
    }
    if (platform == "window") {
        return platform::openWindowDisplay(options);
    }
    if (platform == "kms") {
        return platform::openKmsDisplay(options);
    }
    throw platform::DisplayError("unknown display platform '" + platform +
                                 "' (kms, window, offscreen)");
}

// What a script does to the running kiosk: actions and input events join the frame's queue,
// frames are written once drawn.
class KioskScriptSink final : public ScriptSink {
  public:
    std::vector<workflow::Action> actions;
    std::vector<platform::InputEvent> events;
    std::vector<std::filesystem::path> frames;

    void action(const workflow::Action& a) override { actions.push_back(a); }
    void input(const platform::InputEvent& e) override { events.push_back(e); }
    void saveFrame(const std::filesystem::path& path) override { frames.push_back(path); }
    double maskDice(const std::filesystem::path& mask, const std::filesystem::path& reference,
                    int label) override {
        return kiosk::maskDice(mask, reference, label);
    }
};

std::unique_ptr<ScriptPlayer> makePlayer(const KioskOptions& options) {
    if (!options.script) {
        return nullptr;
    }
    Variables vars;
    if (!options.scan.empty()) {
        vars["SCAN"] = options.scan;
    }
    if (const char* data = std::getenv("STEERSEG_DATA_DIR"); data != nullptr && *data != '\0') {
        vars["DATA"] = data;
    }
    vars["OUT"] =
        options.frames ? options.frames->string() : std::filesystem::current_path().string();
    return std::make_unique<ScriptPlayer>(loadScript(*options.script), std::move(vars));
}

} // namespace

int runKiosk(const KioskOptions& options, std::ostream& out, std::ostream& err) {
    const config::LoadedConfig loaded = readConfig(options, err);
    const config::KioskConfig& cfg = loaded.config;
    std::unique_ptr<ScriptPlayer> player =
        makePlayer(options); // bad scripts fail before a window opens
    if (options.frames) {
        std::filesystem::create_directories(*options.frames);
    }

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
    // The display owns the GL context: it is declared first so everything that holds GL objects
    // goes before it.
    std::unique_ptr<platform::Display> display = openDisplay(platformName, displayOpts);
    const platform::DisplayInfo& info = display->info();
    out << "steerseg kiosk: " << info.description << '\n';
    const double dpi = cfg.display.dpi > 0.0 ? cfg.display.dpi : info.dpi;
    const glm::ivec2 physical(info.width, info.height);
    const ui::ScreenRotation rotation(cfg.display.rotation, physical.x, physical.y);
    ScreenCompositor screen(physical, cfg.display.rotation);

    SessionEngine engine;
    workflow::AuditLog audit(cfg.audit.path);
    workflow::Workflow flow(engine, workflowSettings(cfg), &audit);
    std::vector<std::string> scans{io::kBuiltinSample};
    if (!options.scan.empty()) {
        scans.push_back(options.scan);
    }
    ui::TouchUi touch({dpi, cfg.ui.touchTargetMm, cfg.ui.fontScale, cfg.probe.radiusMm,
                       static_cast<double>(cfg.ui.longPressMs), "", scans});
    const auto layoutOf = [&](const glm::ivec2& size) {
        return ui::computeLayout(size.x, size.y, dpi, cfg.ui.touchTargetMm);
    };
    const KeyBindings keys(cfg.bindings.keys);
    IterationBudget budget(cfg.frame.solverShare, cfg.frame.budgetMs * 1e-3,
                           cfg.frame.minIterations, cfg.frame.maxIterations);
    double lastFrameSeconds = 0.0;
    ViewPainter painter(cfg.frame.interactiveScale);
    FrameStats stats;
    StopSignals signals;

    std::vector<workflow::Action> actions;
    if (!options.scan.empty() && !player) {
        actions.emplace_back(workflow::LoadScan{options.scan});
    }
    KioskScriptSink sink;
    std::vector<platform::InputEvent> events;
    ui::ScreenState screenState{layoutOf(screen.size()), {}, {}};
    std::uint64_t shownScan = 0;
    std::vector<std::filesystem::path> pendingFrames;
    const double frameBudget = cfg.frame.budgetMs * 1e-3;
    double panelSeconds = 0.0; // the panel, composition and present: an average over frames
    const Clock::time_point start = Clock::now();
    double inputSince = -1.0; // the poll that brought the oldest input not yet on screen; -1: none
    int exitCode = 0;

    while (!g_stop) {
        const Clock::time_point frameStart = Clock::now();
        const double now = secondsSince(start);
        events.clear();
        display->pollEvents(events);

        // A script waits while a frame it asked for is still being refined, so the file shows
        // the complete picture of the moment the script meant.
        if (player && pendingFrames.empty()) {
            player->poll(now, flow.status(), sink);
            for (auto& a : sink.actions) {
                actions.push_back(std::move(a));
            }
            // A script's device-level events stand for the display's: physical pixels.
            for (auto& e : sink.events) {
                events.push_back(std::move(e));
            }
            for (auto& f : sink.frames) {
                pendingFrames.push_back(std::move(f));
            }
            sink.actions.clear();
            sink.events.clear();
            sink.frames.clear();
        }
        bool hadInput = !events.empty();
        if (hadInput && inputSince < 0.0) {
            inputSince = now;
        }
        for (const platform::InputEvent& raw : events) {
            if (raw.kind == platform::InputEvent::Kind::Quit) {
                g_stop = true;
                break;
            }
            if (const auto bound = keys.actionFor(raw)) {
                actions.push_back(*bound);
                continue;
            }
            touch.feed(rotation.toLogical(raw), screenState, flow.status(), actions);
        }
        for (const workflow::Action& a : actions) {
            const workflow::Workflow::Outcome o = flow.handle(a);
            if (!o.accepted) {
                err << "steerseg kiosk: " << workflow::actionName(a) << " refused: " << o.reason
                    << '\n';
            }
        }
        hadInput = hadInput || !actions.empty();
        actions.clear();
        flow.update();

        const bool evolving = flow.state() == workflow::State::Evolving;
        double solverSeconds = 0.0;
        if (evolving) {
            if (const int n = budget.next(lastFrameSeconds); n > 0) {
                const Clock::time_point t = Clock::now();
                const solver::StepResult r = flow.evolve(n);
                solverSeconds = secondsSince(t);
                budget.record(r.iterations, solverSeconds);
                stats.iterations(r.iterations, solverSeconds);
            }
        }

        screen.begin({0.08F, 0.08F, 0.09F});
        screenState = {layoutOf(screen.size()), {}, {}};
        if (session::Session* session = engine.session()) {
            if (engine.scansAttached() != shownScan) {
                painter.reset();
                shownScan = engine.scansAttached();
            }
            // The views get what the solver and the panel leave of the frame.
            const double left =
                std::max(frameBudget - solverSeconds - panelSeconds, frameBudget * 0.25);
            screenState = painter.paint(*session, flow.status(), engine.levelSetVersion(),
                                        screenState.layout, left, screen);
            const auto [pixels, seconds] = painter.takeDrawn();
            stats.drawn(pixels, seconds);
        }
        const Clock::time_point panelStart = Clock::now();
        glBindFramebuffer(GL_FRAMEBUFFER, screen.framebuffer());
        std::vector<workflow::Action> panel =
            touch.drawFrame(screen.size(), now, screenState, flow.status());
        for (auto& a : panel) {
            actions.push_back(std::move(a));
        }
        screen.present(display->framebuffer(), physical);
        glFinish(); // the panel's and the present's cost, for the next frame's split
        panelSeconds = 0.8 * panelSeconds + 0.2 * secondsSince(panelStart);
        display->present();
        const double frameSeconds = secondsSince(frameStart);
        lastFrameSeconds = frameSeconds;
        if (engine.session() != nullptr) { // frames showing a scan: not the wait for a load
            stats.frame(frameSeconds, evolving);
        }
        // Input to screen: from the poll that brought an event to the present of the frame that
        // drew all it led to. A panel button acts, and is drawn, a frame later: its actions
        // are still queued here. A script's operator-level actions are no device's input.
        if (inputSince >= 0.0 && actions.empty()) {
            stats.latency(secondsSince(start) - inputSince);
            inputSince = -1.0;
        }

        if (!pendingFrames.empty() && (painter.settled() || evolving || !engine.session())) {
            const RgbaImage picture = screen.capture();
            for (const auto& path : pendingFrames) {
                io::writeImage(path, picture);
            }
            pendingFrames.clear();
        }
        if (flow.quitRequested()) {
            break;
        }
        if (player && (player->finished() || player->failed()) && pendingFrames.empty()) {
            if (player->failed()) {
                err << "steerseg kiosk: " << player->failure() << '\n';
                exitCode = 1;
            }
            break;
        }
        if (options.maxSeconds > 0.0 && secondsSince(start) > options.maxSeconds) {
            err << "steerseg kiosk: stopped after " << options.maxSeconds << " s (--max-seconds)\n";
            exitCode = 1;
            break;
        }
        // Nothing moving and no display pacing the loop: do not spin a core.
        if (info.refreshHz <= 0.0 && !evolving && (painter.settled() || !engine.session()) &&
            !hadInput && pendingFrames.empty()) {
            std::this_thread::sleep_for(std::chrono::milliseconds(5));
        }
    }
    if (const auto error = audit.takeError()) {
        err << "steerseg kiosk: audit log: " << *error << '\n';
    }
    out << stats.summary() << '\n';
    if (options.stats) {
        stats.write(*options.stats, info.description);
    }
    return exitCode;
}

} // namespace steerseg::kiosk
