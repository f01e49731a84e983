#include "input/control_bindings.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <utility>

namespace steerseg::input {

namespace {

using platform::input::ControlEvent;

constexpr double kAccelerationWindow = 0.1; // seconds: "detents per 100 ms"
constexpr double kSlowDetents = 3.0;        // at or below: fine steps
constexpr double kMaxAcceleration = 10.0;
constexpr std::size_t kMaxRecent = 64; // a flood's history stays small
constexpr double kMaxRingRate = 20.0;  // repeats per second at the end stop
constexpr double kRingRest = 1e-6;     // |position| below this is the centre
constexpr int kMaxRepeatsPerTick = 5;  // a long frame does not burst the nudges it missed

} // namespace

double stepAcceleration(double detentsPer100ms) {
    if (!(detentsPer100ms > kSlowDetents)) { // NaN too
        return 1.0;
    }
    return std::min(kMaxAcceleration, 1.0 + (detentsPer100ms - kSlowDetents) / kSlowDetents);
}

double ringRepeatsPerSecond(double position) {
    const double p = std::abs(position);
    return std::isfinite(p) ? kMaxRingRate * std::min(p, 1.0) : 0.0;
}

ControlBindings::ControlBindings(config::BindingTable knobs, config::BindingTable buttons)
    : knobs_(std::move(knobs)), buttons_(std::move(buttons)) {}

bool ControlBindings::bound(std::string_view control) const {
    return knobs_.contains(control) || buttons_.contains(control);
}

std::string ControlBindings::actionName(std::string_view control) const {
    if (const auto k = knobs_.find(control); k != knobs_.end()) {
        return k->second.action;
    }
    if (const auto b = buttons_.find(control); b != buttons_.end()) {
        return b->second.release.empty() ? b->second.action
                                         : b->second.action + " / " + b->second.release;
    }
    return "";
}

bool ControlBindings::repeating() const {
    return std::any_of(rings_.begin(), rings_.end(),
                       [](const auto& ring) { return !ring.second.suppressed; });
}

void ControlBindings::emit(const config::Binding& binding, double steps,
                           std::vector<model::Action>& out) {
    if (auto action = model::bindingAction(binding.action, steps)) {
        out.push_back(std::move(*action));
    }
}

// Last touch wins: a ring that keeps repeating on the action another control was just touched
// for would fight it, so it falls silent until it is moved again.
void ControlBindings::touched(std::string_view control, const std::string& action) {
    for (auto& [name, ring] : rings_) {
        if (name != control && ring.action == action) {
            ring.suppressed = true;
        }
    }
}

double ControlBindings::accelerated(const ControlEvent& event) {
    std::deque<Recent>& recent = recent_[event.control];
    const bool up = event.steps > 0;
    // A turn the other way, or a clock that went back (a new replay), starts afresh.
    if (!recent.empty() && ((recent.back().steps > 0) != up || recent.back().time > event.time)) {
        recent.clear();
    }
    while (!recent.empty() && recent.front().time < event.time - kAccelerationWindow) {
        recent.pop_front();
    }
    if (recent.size() >= kMaxRecent) {
        recent.pop_front();
    }
    recent.push_back({event.time, event.steps});
    double detents = 0.0;
    for (const Recent& r : recent) {
        detents += std::abs(static_cast<double>(r.steps));
    }
    return stepAcceleration(detents);
}

void ControlBindings::feed(const ControlEvent& event, std::vector<model::Action>& out) {
    switch (event.kind) {
    case ControlEvent::Kind::Step: {
        const auto it = knobs_.find(event.control);
        if (it == knobs_.end() || event.steps == 0) {
            return;
        }
        touched(event.control, it->second.action);
        const double factor = accelerated(event);
        emit(it->second, it->second.steps * factor * event.steps, out);
        return;
    }
    case ControlEvent::Kind::Position: {
        const auto it = knobs_.find(event.control);
        if (it == knobs_.end()) {
            return;
        }
        const double p =
            std::clamp(std::isfinite(event.position) ? event.position : 0.0, -1.0, 1.0);
        if (std::abs(p) < kRingRest) {
            rings_.erase(event.control);
            return;
        }
        touched(event.control, it->second.action);
        const double period = 1.0 / ringRepeatsPerSecond(p);
        auto ring = rings_.find(event.control);
        if (ring == rings_.end()) {
            // Off centre: one repeat at once, so the ring answers as it is turned.
            ring = rings_
                       .emplace(event.control, Ring{it->second.action, it->second.steps, p,
                                                    event.time + period, false})
                       .first;
            emit(it->second, p > 0.0 ? it->second.steps : -it->second.steps, out);
            return;
        }
        Ring& r = ring->second;
        // Turned further, it speeds up from now rather than after the slow repeat it was on.
        r.nextDue = std::min(r.nextDue, event.time + period);
        r.position = p;
        r.suppressed = false;
        return;
    }
    case ControlEvent::Kind::Press: {
        const auto it = buttons_.find(event.control);
        if (it != buttons_.end()) {
            touched(event.control, it->second.action);
            emit(it->second, it->second.steps, out);
        }
        return;
    }
    case ControlEvent::Kind::Release: {
        const auto it = buttons_.find(event.control);
        if (it != buttons_.end() && !it->second.release.empty()) {
            emit({it->second.release, it->second.steps, ""}, it->second.steps, out);
        }
        return;
    }
    }
}

void ControlBindings::tick(double now, std::vector<model::Action>& out) {
    for (auto& [name, ring] : rings_) {
        if (ring.suppressed) {
            continue;
        }
        const double period = 1.0 / ringRepeatsPerSecond(ring.position);
        const config::Binding binding{ring.action, ring.steps, ""};
        int repeats = 0;
        while (ring.nextDue <= now && repeats < kMaxRepeatsPerTick) {
            emit(binding, ring.position > 0.0 ? ring.steps : -ring.steps, out);
            ring.nextDue += period;
            ++repeats;
        }
        if (ring.nextDue <= now) {
            ring.nextDue = now + period;
        }
    }
}

} // namespace steerseg::input
