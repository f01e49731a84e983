#pragma once

// Pointer events -> gestures: tap, long press, drag, pinch, wheel. Pure and clocked by the
// events' own times (and update(now) between events, so a finger held still reports its long
// press while it is still down), so a recorded session recognises the same gestures.
#include "platform/input_event.hpp"

#include <array>
#include <glm/glm.hpp>
#include <vector>

namespace steerseg::ui {

struct GestureConfig {
    double slopPx = 8.0;     // a finger that stays within this of where it went down is still
    double longPressS = 0.6; // ... and held this long is a long press
};
// Slop of `slopMm` (2 mm by default) at `dpi` (96 where not a positive finite number).
GestureConfig gestureConfig(double dpi, double slopMm = 2.0, double longPressMs = 600.0);

struct Gesture {
    enum class Kind {
        Tap,       // down and up within the slop, sooner than a long press
        LongPress, // held still: reported once, while still held
        Drag,      // one finger moved beyond the slop: `delta` since the last Drag; a last
                   // one with `lifted` when that finger lifts (not when a second finger
                   // turns the drag into a pinch: a painted stroke then has no end)
        Pinch,     // two fingers: `scale` since the last Pinch (> 1 = apart), about `position`
        Wheel,     // `wheel` detents at `position`
    };
    Kind kind = Kind::Tap;
    int id = 0;               // the same for all events of one gesture (a drag, a pinch)
    glm::dvec2 start{0.0};    // where the gesture began (its region decides its meaning)
    glm::dvec2 position{0.0}; // where it is now (pinch: the two fingers' centre)
    glm::dvec2 delta{0.0};    // Drag
    double scale = 1.0;       // Pinch
    double wheel = 0.0;       // Wheel
    bool lifted = false;      // Drag: the finger lifted here (delta 0), the drag is over
    double time = 0.0;
};

class GestureRecognizer {
  public:
    static constexpr int kMaxPointers = 16; // slots beyond are ignored

    explicit GestureRecognizer(GestureConfig config = {});

    // Key and quit events, unknown slots, an up without a down and positions that are not
    // finite numbers produce nothing.
    std::vector<Gesture> feed(const platform::InputEvent& event);
    // A long press due by `now`, if any.
    std::vector<Gesture> update(double now);
    void reset();

    [[nodiscard]] int pointersDown() const;
    [[nodiscard]] const GestureConfig& config() const { return config_; }

  private:
    enum class Mode { Idle, Pending, Held, Dragging, Pinching, Cancelled };
    struct Pointer {
        bool down = false;
        glm::dvec2 position{0.0};
    };
    void pointerDown(int slot, const glm::dvec2& p, double time, std::vector<Gesture>& out);
    void pointerMove(int slot, const glm::dvec2& p, double time, std::vector<Gesture>& out);
    void pointerUp(int slot, double time, std::vector<Gesture>& out);
    [[nodiscard]] Gesture make(Gesture::Kind kind, double time) const;
    void pinchPair(glm::dvec2& centre, double& distance) const;

    GestureConfig config_;
    std::array<Pointer, kMaxPointers> pointers_{};
    Mode mode_ = Mode::Idle;
    int id_ = 0;
    int primary_ = -1; // the first finger of a tap, press or drag
    int second_ = -1;  // the pinch's other finger
    glm::dvec2 start_{0.0};
    double startTime_ = 0.0;
    glm::dvec2 last_{0.0};
    double lastDistance_ = 0.0;
};

} // namespace steerseg::ui
