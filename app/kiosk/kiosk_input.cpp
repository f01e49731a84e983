// The kiosk's input pass: the display's events, a script's due steps and the devices'
// reports, each through its own decoding, turned into the workflow's actions.
#include "kiosk/kiosk.hpp"
#include "kiosk/kiosk_startup.hpp"
#include "platform/input/recording.hpp"

#include <ostream>
#include <utility>

namespace steerseg::kiosk {

bool Kiosk::pollInput() {
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

input::InputHubLimits Kiosk::hubLimits() {
    input::InputHubLimits limits;
    limits.logPrefix = kLogPrefix;
    return limits;
}

void Kiosk::replayRecording(const std::filesystem::path& path) {
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

} // namespace steerseg::kiosk
