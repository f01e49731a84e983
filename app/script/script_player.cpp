#include "script/script_player.hpp"

#include "script/script_condition.hpp"

#include <algorithm>
#include <cstdio>
#include <exception>
#include <set>
#include <stdexcept>
#include <type_traits>

namespace steerseg::script {

void ScriptSink::raw(const platform::input::RawRecord& /*record*/) {
    throw std::runtime_error("raw device input is not taken here");
}

void ScriptSink::replay(const std::filesystem::path& /*recording*/) {
    throw std::runtime_error("recordings are not replayed here");
}

namespace {

std::string seconds(double s) {
    char text[32];
    std::snprintf(text, sizeof text, "%.3g s", s);
    return text;
}

// "" when the PACS action names no peer or one of the status's query peers; else why not.
std::string unknownPeer(const model::Action& action, const workflow::Status& status) {
    std::string peer;
    if (const auto* s = std::get_if<model::SearchPacs>(&action)) {
        peer = s->peer;
    } else if (const auto* l = std::get_if<model::ListPacsSeries>(&action)) {
        peer = l->peer;
    } else if (const auto* r = std::get_if<model::RetrievePacs>(&action)) {
        peer = r->peer;
    }
    const std::vector<std::string>& peers = status.pacs.peers;
    if (peer.empty() || std::find(peers.begin(), peers.end(), peer) != peers.end()) {
        return "";
    }
    std::string known;
    for (const std::string& p : peers) {
        known += (known.empty() ? "" : ", ") + p;
    }
    return "no query peer named '" + peer + "' (" +
           (known.empty() ? "none in the config" : "the config's: " + known) + ")";
}

// Replaces $NAME and ${NAME} with the values of `lookup`; names it cannot give go to `missing`
// and stay as written.
template <typename Lookup>
std::string expand(const std::string& text, const Lookup& lookup, std::set<std::string>* missing) {
    std::string out;
    for (std::size_t n = 0; n < text.size(); ++n) {
        if (text[n] != '$') {
            out += text[n];
            continue;
        }
        const bool braced = n + 1 < text.size() && text[n + 1] == '{';
        const std::size_t begin = n + (braced ? 2 : 1);
        std::size_t end = begin;
        while (end < text.size() && ((text[end] >= 'A' && text[end] <= 'Z') || text[end] == '_' ||
                                     (end > begin && text[end] >= '0' && text[end] <= '9'))) {
            ++end;
        }
        const std::string name = text.substr(begin, end - begin);
        const std::size_t after = braced ? end + 1 : end;
        if (const std::string* value = lookup(name)) {
            out += *value;
        } else {
            if (missing != nullptr) {
                missing->insert(name);
            }
            out += text.substr(n, after - n);
        }
        n = after - 1;
    }
    return out;
}

const char* howToSet(const std::string& name) {
    if (name == "SCAN") {
        return "$SCAN is not set (give --scan PATH)";
    }
    if (name == "DATA") {
        return "$DATA is not set (set STEERSEG_DATA_DIR to the folder of real scans)";
    }
    if (name == "OUT") {
        return "$OUT is not set (give --frames DIR)";
    }
    return nullptr;
}

bool isRelative(const std::string& path) {
    return !path.empty() && std::filesystem::path(path).is_relative();
}

} // namespace

ScriptPlayer::ScriptPlayer(Script script, Variables variables)
    : script_(std::move(script)), variables_(std::move(variables)) {
    std::string errors;
    // Given variables now, so a missing --scan is said before anything runs; EXPORTED and
    // RECEIVED later.
    const auto given = [this](const std::string& name) -> const std::string* {
        if (name == "EXPORTED" || name == "RECEIVED" || name == "FOUND" || name == "SERIES") {
            return nullptr;
        }
        const auto it = variables_.find(name);
        return it == variables_.end() ? nullptr : &it->second;
    };
    for (Step& step : script_.steps) {
        std::set<std::string> missing;
        const auto fill = [&](std::string& text) { text = expand(text, given, &missing); };
        std::visit(
            [&](auto& kind) {
                using K = std::decay_t<decltype(kind)>;
                if constexpr (std::is_same_v<K, ActionStep>) {
                    if (auto* load = std::get_if<model::LoadScan>(&kind.action)) {
                        fill(load->path);
                    } else if (auto* out = std::get_if<model::Export>(&kind.action)) {
                        fill(out->path);
                    } else if (auto* get = std::get_if<model::RetrievePacs>(&kind.action)) {
                        fill(get->studyUid);
                        fill(get->seriesUid);
                    } else if (auto* list = std::get_if<model::ListPacsSeries>(&kind.action)) {
                        fill(list->studyUid);
                    }
                } else if constexpr (std::is_same_v<K, FrameStep>) {
                    fill(kind.path);
                } else if constexpr (std::is_same_v<K, DiceStep>) {
                    fill(kind.mask);
                    fill(kind.reference);
                } else if constexpr (std::is_same_v<K, RawStep>) {
                    fill(kind.recording);
                }
            },
            step.kind);
        missing.erase("EXPORTED");
        missing.erase("RECEIVED");
        missing.erase("FOUND");
        missing.erase("SERIES");
        for (const std::string& name : missing) {
            const char* how = howToSet(name);
            errors += (errors.empty() ? "" : "\n") + script_.name + ":" +
                      std::to_string(step.line) + ": " +
                      (how != nullptr ? std::string(how) : "$" + name + " is not set");
        }
    }
    if (!errors.empty()) {
        throw ScriptError(errors);
    }
}

std::string ScriptPlayer::runtimePath(const std::string& path, const workflow::Status& status,
                                      bool underOut) const {
    // RECEIVED: the newest series the DICOM node has received completely ("" when none).
    std::string received;
    for (const workflow::ReceivedScan& r : status.received) {
        if (!r.arriving) {
            received = r.path;
            break;
        }
    }
    // FOUND: the first study the last PACS search found ("" when none).
    const std::string found =
        status.pacs.studies.empty() ? std::string() : status.pacs.studies.front().studyUid;
    // SERIES: the first series the last series listing found ("" when none).
    const std::string series =
        status.pacs.series.empty() ? std::string() : status.pacs.series.front().seriesUid;
    const auto runtime = [&](const std::string& name) -> const std::string* {
        if (name == "FOUND") {
            return &found;
        }
        if (name == "SERIES") {
            return &series;
        }
        return name == "EXPORTED" ? &status.exportedPath
                                  : (name == "RECEIVED" ? &received : nullptr);
    };
    std::string resolved = expand(path, runtime, nullptr);
    const auto out = variables_.find("OUT");
    if (underOut && out != variables_.end() && isRelative(resolved)) {
        resolved = (std::filesystem::path(out->second) / resolved).string();
    }
    return resolved;
}

void ScriptPlayer::complete(double at) {
    previousDone_ = at;
    ++next_;
    waiting_ = false;
}

void ScriptPlayer::fail(const Step& step, const std::string& reason) {
    failure_ = script_.name + ":" + std::to_string(step.line) + ": " + step.text + ": " + reason;
}

void ScriptPlayer::poll(double now, const workflow::Status& status, ScriptSink& sink) {
    if (failed() || finished()) {
        return;
    }
    if (!started_) {
        started_ = true;
        start_ = now;
        previousDone_ = now;
        lastNow_ = now;
    }
    if (now < lastNow_) {
        failure_ = script_.name + ": the script clock went back from " + seconds(lastNow_) +
                   " to " + seconds(now);
        return;
    }
    lastNow_ = now;
    bool emitted = false; // an action this call: the status does not show it yet
    while (next_ < script_.steps.size() && !failed()) {
        const Step& step = script_.steps[next_];
        double due = previousDone_;
        if (step.timing.kind == Timing::At) {
            due = start_ + step.timing.seconds;
        } else if (step.timing.kind == Timing::After) {
            due = previousDone_ + step.timing.seconds;
        }
        if (now < due) {
            return;
        }
        // Timed steps keep their schedule (a late frame does not push the next ones back);
        // waits and checks are done when the frame that satisfies them comes.
        const double scheduled = std::max(due, previousDone_);
        const bool needsFreshStatus = std::holds_alternative<WaitStep>(step.kind) ||
                                      std::holds_alternative<ExpectStep>(step.kind) ||
                                      std::holds_alternative<DiceStep>(step.kind);
        if (needsFreshStatus && emitted) {
            return;
        }
        try {
            if (const auto* input = std::get_if<InputStep>(&step.kind)) {
                for (platform::InputEvent event : input->events) {
                    event.time = now;
                    sink.input(event);
                }
                emitted = true;
                complete(scheduled);
            } else if (const auto* act = std::get_if<ActionStep>(&step.kind)) {
                model::Action action = act->action;
                if (auto* out = std::get_if<model::Export>(&action)) {
                    out->path = runtimePath(out->path, status, true);
                } else if (auto* load = std::get_if<model::LoadScan>(&action)) {
                    load->path = runtimePath(load->path, status, false);
                } else if (auto* get = std::get_if<model::RetrievePacs>(&action)) {
                    get->studyUid = runtimePath(get->studyUid, status, false);
                    get->seriesUid = runtimePath(get->seriesUid, status, false);
                } else if (auto* list = std::get_if<model::ListPacsSeries>(&action)) {
                    list->studyUid = runtimePath(list->studyUid, status, false);
                }
                if (const std::string problem = unknownPeer(action, status); !problem.empty()) {
                    fail(step, problem);
                    return;
                }
                sink.action(action);
                emitted = true;
                complete(scheduled);
            } else if (const auto* frame = std::get_if<FrameStep>(&step.kind)) {
                sink.saveFrame(runtimePath(frame->path, status, true));
                complete(scheduled);
                // The frame shows the screen as the steps before it left it: the steps after
                // it wait for the next call.
                return;
            } else if (const auto* wait = std::get_if<WaitStep>(&step.kind)) {
                if (!pollWait(step, *wait, now, status)) {
                    return;
                }
            } else if (const auto* expect = std::get_if<ExpectStep>(&step.kind)) {
                if (!holds(expect->condition, status)) {
                    fail(step, observed(expect->condition, status));
                    return;
                }
                complete(now);
            } else if (const auto* dice = std::get_if<DiceStep>(&step.kind)) {
                runDice(step, *dice, status, sink);
            } else if (const auto* raw = std::get_if<RawStep>(&step.kind)) {
                if (raw->record) {
                    // Stamped when the step was due, as a device stamps a record when it
                    // happened, not when it is read: after a late frame several records are
                    // due at once, and the decoders' rates (a knob's acceleration, a ring's
                    // repeats) must see them as far apart as the script put them.
                    platform::input::RawRecord record = *raw->record;
                    record.time = scheduled;
                    sink.raw(record);
                } else {
                    sink.replay(runtimePath(raw->recording, status, false));
                }
                emitted = true;
                complete(scheduled);
            } else if (const auto* answer = std::get_if<AutosaveStep>(&step.kind)) {
                sink.answerResume(answer->resume);
                emitted = true;
                complete(scheduled);
            }
        } catch (const std::exception& e) {
            fail(step, e.what());
        }
    }
}

bool ScriptPlayer::pollWait(const Step& step, const WaitStep& wait, double now,
                            const workflow::Status& status) {
    const Condition& c = wait.condition;
    if (!waiting_) {
        waiting_ = true;
        waitStart_ = now;
        waitBaseIterations_ = status.iterations;
        waitSawEvolving_ = false;
    }
    const double waited = now - waitStart_;
    bool done = false;
    if (c.kind == Condition::Seconds) {
        done = waited >= c.value;
    } else if (c.kind == Condition::Iterations) {
        // A restart drops the count: count from there.
        waitBaseIterations_ = std::min(waitBaseIterations_, status.iterations);
        done = status.iterations - waitBaseIterations_ >= c.count;
    } else {
        done = holds(c, status);
    }
    if (done) {
        complete(now);
        return true;
    }
    const bool waitsForError = c.kind == Condition::State && c.state == model::State::Error;
    if (status.state == model::State::Error && !waitsForError) {
        fail(step, "the workflow is in error: " + status.message);
        return true;
    }
    if (c.kind == Condition::Loaded && status.state == model::State::NoScan &&
        !status.message.empty()) {
        fail(step, "the scan did not load: " + status.message);
        return true;
    }
    // The solver stopping (convergence, a pause) before the count is a failure now, not after
    // the timeout; a status from before the run began does not count.
    if (c.kind == Condition::Iterations) {
        if (status.state == model::State::Evolving) {
            waitSawEvolving_ = true;
        } else if (waitSawEvolving_) {
            fail(step, "the solver stopped (" + observed(c, status) + ") after " +
                           std::to_string(status.iterations - waitBaseIterations_) + " of " +
                           std::to_string(c.count) + " iterations");
            return true;
        }
    }
    if (c.kind != Condition::Seconds && waited >= wait.timeoutSeconds) {
        fail(step,
             "timed out after " + seconds(wait.timeoutSeconds) + " (" + observed(c, status) + ")");
        return true;
    }
    return false;
}

void ScriptPlayer::runDice(const Step& step, const DiceStep& dice, const workflow::Status& status,
                           ScriptSink& sink) {
    const std::string mask = runtimePath(dice.mask, status, true);
    if (mask.empty()) {
        fail(step, "no mask to compare (nothing was exported yet)");
        return;
    }
    const double value =
        sink.maskDice(mask, runtimePath(dice.reference, status, false), dice.label);
    if (!compare(value, dice.op, dice.value)) {
        char text[96];
        std::snprintf(text, sizeof text, "Dice is %.4f", value);
        fail(step, text);
        return;
    }
    complete(lastNow_);
}

} // namespace steerseg::script
