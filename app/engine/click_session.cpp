#include "engine/click_session.hpp"

#include <algorithm>
#include <chrono>
#include <stdexcept>
#include <thread>
#include <variant>

namespace steerseg::engine {

namespace {

using Clock = std::chrono::steady_clock;

double since(Clock::time_point t) {
    return std::chrono::duration<double>(Clock::now() - t).count();
}

// Iterations per evolve call: the kiosk's frame takes a few to a few tens; the solver reads its
// counters every checkInterval anyway, so a whole interval costs no extra readback.
constexpr int kChunk = 16;

} // namespace

ClickSession::ClickSession(const std::string& scanPath, const workflow::Settings& settings,
                           EdgeSpeedRules edge, model::SolverOptions options)
    : engine_(options, edge), flow_(engine_, settings) {
    const workflow::Workflow::Outcome load = flow_.handle(model::LoadScan{scanPath});
    if (!load.accepted) {
        throw std::runtime_error(scanPath + ": " + load.reason);
    }
    while (flow_.state() == model::State::Loading) {
        flow_.update();
        if (flow_.state() == model::State::Loading) {
            std::this_thread::sleep_for(std::chrono::milliseconds(5));
        }
    }
    if (flow_.state() != model::State::Inspect) {
        throw std::runtime_error(scanPath + ": " + flow_.status().message);
    }
}

ClickOutcome ClickSession::apply(const model::Action& prompt, int maxIterations) {
    const auto start = Clock::now();
    const WorkSeconds workBefore = engine_.workSeconds();
    const int takenBackBefore = flow_.status().eraseRunsTakenBack;
    const int withdrawOnlyBefore = flow_.status().erasesWithdrawOnly;
    const workflow::Workflow::Outcome out = flow_.handle(prompt);
    const std::string what = std::holds_alternative<model::SetBox>(prompt) ? "box" : "click";
    if (!out.accepted) {
        throw std::runtime_error("the " + what + " was refused: " + out.reason);
    }
    // A box leaves its seed for the operator to run (the kiosk's run button); a robot runs it.
    if (flow_.status().hasLevelSet &&
        (flow_.state() == model::State::Seeding || flow_.state() == model::State::Paused)) {
        if (const auto run = flow_.handle(model::Run{}); !run.accepted) {
            throw std::runtime_error("the " + what + "'s run was refused: " + run.reason);
        }
    }
    ClickOutcome r;
    engine_.session()->finishGpuWork();
    r.firstChangeSeconds = since(start);
    r.firstChangeWork = engine_.workSeconds() - workBefore;
    engine_.keepUndoWithinBudget(); // as the kiosk does after the frame that shows the change
    const int startIterations = engine_.stats().iterations;
    int done = 0;
    model::StepResult last;
    while (flow_.state() == model::State::Evolving && done < maxIterations) {
        last = flow_.evolve(std::min(kChunk, maxIterations - done));
        done = engine_.stats().iterations - startIterations;
        if (last.iterations == 0) {
            break; // the workflow left evolving (an error says why) or the engine did nothing
        }
    }
    if (flow_.state() == model::State::Evolving) {
        flow_.handle(model::Pause{});
    }
    engine_.session()->finishGpuWork();
    r.seconds = since(start);
    if (!flow_.status().hasLevelSet) {
        r.stopReason = "vanished";
    } else if (last.stopReason == model::StopReason::Leak) {
        r.stopReason = "leak";
        r.leakWatch = last.leak ? model::leakSignName(last.leak->sign) : "";
    } else if (flow_.status().converged) {
        r.stopReason = "converged";
    } else if (flow_.state() == model::State::Error) {
        throw std::runtime_error("the solver failed: " + flow_.status().message);
    } else {
        r.stopReason = "iteration_limit";
    }
    r.iterations = engine_.stats().iterations;
    r.T = static_cast<double>(flow_.status().params.T);
    r.eps = static_cast<double>(flow_.status().params.eps);
    r.barriers = engine_.barriers();
    r.takenBack = flow_.status().eraseRunsTakenBack != takenBackBefore;
    r.withdrawOnly = flow_.status().erasesWithdrawOnly != withdrawOnlyBefore;
    return r;
}

std::vector<std::uint8_t> ClickSession::mask() {
    return engine_.session()->mask();
}

const Volume& ClickSession::scan() {
    return engine_.session()->scan();
}

} // namespace steerseg::engine
