#include "ui/gestures.hpp"

#include <algorithm>
#include <cmath>

namespace steerseg::ui {

namespace {

constexpr double kMinPinchDistance = 1.0; // px: closer fingers give no meaningful scale

bool finite(const glm::dvec2& p) {
    return std::isfinite(p.x) && std::isfinite(p.y);
}

} // namespace

GestureConfig gestureConfig(double dpi, double slopMm, double longPressMs) {
    if (!(dpi > 0.0) || !std::isfinite(dpi)) {
        dpi = 96.0;
    }
    GestureConfig c;
    if (!(slopMm > 0.0) || !std::isfinite(slopMm)) {
        slopMm = 2.0;
    }
    c.slopPx = slopMm * dpi / 25.4;
    if (longPressMs > 0.0 && std::isfinite(longPressMs)) {
        c.longPressS = longPressMs / 1000.0;
    }
    return c;
}

GestureRecognizer::GestureRecognizer(GestureConfig config) : config_(config) {}

void GestureRecognizer::reset() {
    pointers_ = {};
    mode_ = Mode::Idle;
    primary_ = -1;
    second_ = -1;
}

int GestureRecognizer::pointersDown() const {
    return static_cast<int>(
        std::count_if(pointers_.begin(), pointers_.end(), [](const Pointer& p) { return p.down; }));
}

Gesture GestureRecognizer::make(Gesture::Kind kind, double time) const {
    Gesture g;
    g.kind = kind;
    g.id = id_;
    g.start = start_;
    g.position = last_;
    g.time = time;
    return g;
}

void GestureRecognizer::pinchPair(glm::dvec2& centre, double& distance) const {
    const glm::dvec2 a = pointers_[static_cast<std::size_t>(primary_)].position;
    const glm::dvec2 b = pointers_[static_cast<std::size_t>(second_)].position;
    centre = 0.5 * (a + b);
    distance = glm::length(a - b);
}

std::vector<Gesture> GestureRecognizer::update(double now) {
    std::vector<Gesture> out;
    if (mode_ == Mode::Pending && std::isfinite(now) && now - startTime_ >= config_.longPressS) {
        mode_ = Mode::Held;
        out.push_back(make(Gesture::Kind::LongPress, now));
    }
    return out;
}

std::vector<Gesture> GestureRecognizer::feed(const platform::InputEvent& e) {
    using Kind = platform::InputEvent::Kind;
    std::vector<Gesture> out;
    const glm::dvec2 p(e.x, e.y);
    if (e.kind == Kind::Wheel) {
        if (finite(p) && std::isfinite(e.wheel) && e.wheel != 0.0F) {
            ++id_;
            Gesture g;
            g.kind = Gesture::Kind::Wheel;
            g.id = id_;
            g.start = p;
            g.position = p;
            g.wheel = static_cast<double>(e.wheel);
            g.time = e.time;
            out.push_back(g);
        }
        return out;
    }
    if (e.kind != Kind::PointerDown && e.kind != Kind::PointerMove && e.kind != Kind::PointerUp) {
        return out;
    }
    if (e.pointer < 0 || e.pointer >= kMaxPointers) {
        return out;
    }
    out = update(e.time);
    if (e.kind == Kind::PointerUp) {
        // A lifted finger is released even when its last position is garbage.
        pointerUp(e.pointer, e.time, out);
    } else if (finite(p)) {
        if (e.kind == Kind::PointerDown) {
            pointerDown(e.pointer, p, e.time, out);
        } else {
            pointerMove(e.pointer, p, e.time, out);
        }
    }
    return out;
}

void GestureRecognizer::pointerDown(int slot, const glm::dvec2& p, double time,
                                    std::vector<Gesture>& /*out*/) {
    Pointer& ptr = pointers_[static_cast<std::size_t>(slot)];
    if (ptr.down) {
        return; // a repeated down: keep the gesture as it is
    }
    ptr.down = true;
    ptr.position = p;
    const int down = pointersDown();
    if (down == 1) {
        ++id_;
        mode_ = Mode::Pending;
        primary_ = slot;
        start_ = p;
        last_ = p;
        startTime_ = time;
    } else if (down == 2 && (mode_ == Mode::Pending || mode_ == Mode::Dragging)) {
        ++id_;
        mode_ = Mode::Pinching;
        second_ = slot;
        glm::dvec2 centre;
        pinchPair(centre, lastDistance_);
        start_ = centre;
        last_ = centre;
    } else {
        // A third finger, or a second after a long press: not a gesture we know; wait for all
        // fingers to lift.
        mode_ = Mode::Cancelled;
    }
}

void GestureRecognizer::pointerMove(int slot, const glm::dvec2& p, double time,
                                    std::vector<Gesture>& out) {
    Pointer& ptr = pointers_[static_cast<std::size_t>(slot)];
    if (!ptr.down) {
        return; // hover
    }
    ptr.position = p;
    if (mode_ == Mode::Pending && slot == primary_) {
        if (glm::length(p - start_) > config_.slopPx) {
            mode_ = Mode::Dragging;
            Gesture g = make(Gesture::Kind::Drag, time);
            g.position = p;
            g.delta = p - start_; // the motion within the slop counts too
            last_ = p;
            out.push_back(g);
        }
    } else if (mode_ == Mode::Dragging && slot == primary_) {
        Gesture g = make(Gesture::Kind::Drag, time);
        g.position = p;
        g.delta = p - last_;
        last_ = p;
        out.push_back(g);
    } else if (mode_ == Mode::Pinching && (slot == primary_ || slot == second_)) {
        glm::dvec2 centre;
        double distance = 0.0;
        pinchPair(centre, distance);
        if (distance >= kMinPinchDistance && lastDistance_ >= kMinPinchDistance) {
            Gesture g = make(Gesture::Kind::Pinch, time);
            g.position = centre;
            g.delta = centre - last_;
            g.scale = distance / lastDistance_;
            out.push_back(g);
        }
        last_ = centre;
        lastDistance_ = distance;
    }
}

void GestureRecognizer::pointerUp(int slot, double time, std::vector<Gesture>& out) {
    Pointer& ptr = pointers_[static_cast<std::size_t>(slot)];
    if (!ptr.down) {
        return; // an up without a down
    }
    ptr.down = false;
    if (mode_ == Mode::Pending && slot == primary_) {
        Gesture g = make(Gesture::Kind::Tap, time);
        g.position = start_;
        out.push_back(g);
    } else if (mode_ == Mode::Dragging && slot == primary_) {
        Gesture g = make(Gesture::Kind::Drag, time);
        g.lifted = true;
        out.push_back(g);
    } else if (mode_ == Mode::Pinching) {
        mode_ = Mode::Cancelled; // the finger left behind neither taps nor drags
    }
    if (pointersDown() == 0) {
        mode_ = Mode::Idle;
        primary_ = -1;
        second_ = -1;
    } else if (slot == primary_ && mode_ != Mode::Cancelled) {
        mode_ = Mode::Cancelled;
    }
}

} // namespace steerseg::ui
