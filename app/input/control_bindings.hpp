#pragma once

// Knobs, rings, buttons and pedals -> the workflow's actions, through the config's
// [bindings.knobs] and [bindings.buttons] tables (docs/input-devices.md, "Bindings"). Pure: the
// caller gives the clock (control events carry their time; tick() takes the frame's), so a
// recording replays to the same actions. Clamping to a parameter's range is the workflow's.
#include "config/kiosk_config.hpp"
#include "model/action.hpp"
#include "platform/input/control_event.hpp"

#include <deque>
#include <map>
#include <string>
#include <string_view>
#include <vector>

namespace steerseg::input {

// A relative control turned fast counts more: with `rate` = the detents of this control in the
// last 100 ms (this event's included, the same direction), each detent counts
// 1 + (rate - 3) / 3, between 1 and 10. Three detents in 100 ms (a slow turn) stay fine steps; a
// flick of 30 detents moves ten times as far.
double stepAcceleration(double detentsPer100ms);

// A ring held off centre repeats its action 20 * |position| times a second (|position| in
// 0..1: the ShuttleXpress's first notch, 1/7, about 3 a second; the end stop 20).
double ringRepeatsPerSecond(double position);

class ControlBindings {
  public:
    ControlBindings(config::BindingTable knobs, config::BindingTable buttons);

    // The actions of one event, appended to `out`. Step and Position go through the knobs
    // table, Press and Release through the buttons table; an unbound control does nothing.
    void feed(const platform::input::ControlEvent& event, std::vector<model::Action>& out);
    // The repeats of the rings held off centre that are due by `now` (the events' clock).
    void tick(double now, std::vector<model::Action>& out);

    [[nodiscard]] bool bound(std::string_view control) const;
    // The binding's action name for a control ("" = unbound), for input-monitor's listing.
    [[nodiscard]] std::string actionName(std::string_view control) const;
    // Whether any ring is off centre (the kiosk keeps its frames coming while one is).
    [[nodiscard]] bool repeating() const;

  private:
    struct Ring {
        std::string action; // the binding's action name: what "last touch wins" compares
        double steps = 0.0;
        double position = 0.0;
        double nextDue = 0.0;
        bool suppressed = false; // another control on the same action was touched since
    };
    struct Recent {
        double time = 0.0;
        int steps = 0;
    };

    void touched(std::string_view control, const std::string& action);
    void emit(const config::Binding& binding, double steps, std::vector<model::Action>& out);
    double accelerated(const platform::input::ControlEvent& event);

    config::BindingTable knobs_;
    config::BindingTable buttons_;
    std::map<std::string, Ring, std::less<>> rings_;
    std::map<std::string, std::deque<Recent>, std::less<>> recent_;
};

} // namespace steerseg::input
