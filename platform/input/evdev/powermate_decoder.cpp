// Griffin PowerMate through its evdev node: EV_REL/REL_DIAL turns and EV_KEY/BTN_0 presses,
// committed at each EV_SYN/SYN_REPORT as the kernel means them. SYN_DROPPED says the kernel's
// buffer overflowed: the frame in progress and everything up to the next SYN_REPORT is
// incomplete, so it is dropped rather than half applied.
#include "platform/input/decoder_records.hpp"
#include "platform/input/decoders.hpp"
#include "platform/input/problem_log.hpp"

#include <algorithm>
#include <limits>
#include <linux/input-event-codes.h>

namespace steerseg::platform::input {

namespace {

// A frame longer than this (no SYN_REPORT in sight) is committed early, so a stream without
// SYN events cannot grow memory; turns merge, so only alternating presses fill it.
constexpr std::size_t kMaxPending = 64;

class PowerMateDecoder final : public Decoder {
  public:
    explicit PowerMateDecoder(const std::string& name)
        : turn_(name + "_turn"), press_(name + "_press"), name_(name) {}

    void feed(const RawRecord& record, std::vector<ControlEvent>& out) override {
        switch (record.kind) {
        case RawRecord::Kind::Evdev:
            event(record, out);
            return;
        default:
            feedOtherRecord(*this, record, out, problems_, name_, "an evdev");
            return;
        }
    }

    void tick(double /*now*/, std::vector<ControlEvent>& /*out*/) override {}

    void reset(double now, std::vector<ControlEvent>& out) override {
        pending_.clear();
        dropping_ = false;
        pressed_ = committedPressed_;
        if (committedPressed_) {
            committedPressed_ = pressed_ = false;
            out.push_back({ControlEvent::Kind::Release, now, press_, 0, 0.0});
        }
    }

    std::vector<std::string> takeProblems() override { return problems_.take(); }

  private:
    void event(const RawRecord& r, std::vector<ControlEvent>& out) {
        if (r.type == EV_SYN) {
            if (r.code == SYN_REPORT) {
                if (!dropping_) {
                    commit(out);
                }
                dropping_ = false;
            } else if (r.code == SYN_DROPPED) {
                if (!dropping_) {
                    problems_.add(name_ + ": the kernel dropped events (SYN_DROPPED); skipping "
                                          "to the next SYN_REPORT");
                }
                pending_.clear();
                pressed_ = committedPressed_;
                dropping_ = true;
            }
            return;
        }
        if (dropping_) {
            return;
        }
        if (r.type == EV_REL && r.code == REL_DIAL) {
            if (r.value == 0) {
                return;
            }
            if (!pending_.empty() && pending_.back().kind == ControlEvent::Kind::Step) {
                // Saturate rather than overflow when a flood sums beyond int.
                const long long sum = static_cast<long long>(pending_.back().steps) + r.value;
                pending_.back().steps = static_cast<int>(std::clamp<long long>(
                    sum, std::numeric_limits<int>::min() / 2, std::numeric_limits<int>::max() / 2));
                pending_.back().time = r.time;
            } else {
                add({ControlEvent::Kind::Step, r.time, turn_, r.value, 0.0}, out);
            }
        } else if (r.type == EV_KEY && r.code == BTN_0) {
            if (r.value == 2) {
                return; // autorepeat: the button is simply still held
            }
            if (r.value != 0 && r.value != 1) {
                problems_.add(name_ + ": BTN_0 value " + std::to_string(r.value) + " (ignored)");
                return;
            }
            const bool down = r.value == 1;
            if (down != pressed_) {
                pressed_ = down;
                add({down ? ControlEvent::Kind::Press : ControlEvent::Kind::Release, r.time, press_,
                     0, 0.0},
                    out);
            }
        }
        // Other events (EV_MSC echoes of the LED, other codes) carry nothing we bind.
    }

    void add(ControlEvent e, std::vector<ControlEvent>& out) {
        pending_.push_back(std::move(e));
        if (pending_.size() >= kMaxPending) {
            commit(out);
        }
    }

    void commit(std::vector<ControlEvent>& out) {
        for (ControlEvent& e : pending_) {
            out.push_back(std::move(e));
        }
        pending_.clear();
        committedPressed_ = pressed_;
    }

    std::string turn_;
    std::string press_;
    std::string name_;
    ProblemLog problems_;
    std::vector<ControlEvent> pending_; // the frame since the last SYN_REPORT
    bool pressed_ = false;              // including the pending frame
    bool committedPressed_ = false;     // as the events sent so far say
    bool dropping_ = false;
};

} // namespace

std::unique_ptr<Decoder> makePowerMateDecoder(const DeviceSpec& spec) {
    return std::make_unique<PowerMateDecoder>(spec.name);
}

} // namespace steerseg::platform::input
