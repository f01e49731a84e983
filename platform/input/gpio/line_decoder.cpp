// A GPIO input line (a foot pedal, a panel button) with software debounce. A contact bounces
// for a few milliseconds when it closes or opens. The first edge of a quiet line is taken at
// once, so a press feels immediate; the edges that follow within the debounce time only move
// the pending level, and once the line has been quiet that long the settled level is sent if
// it differs from the last one sent. A bounce that ends released gives Press then Release; a
// clean press gives one Press; a held pedal stays pressed without repeats.
#include "platform/input/decoder_records.hpp"
#include "platform/input/decoders.hpp"
#include "platform/input/problem_log.hpp"

#include <cmath>
#include <optional>

namespace steerseg::platform::input {

namespace {

class GpioLineDecoder final : public Decoder {
  public:
    GpioLineDecoder(std::string name, double debounceSeconds)
        : name_(std::move(name)),
          debounce_(std::isfinite(debounceSeconds) && debounceSeconds > 0.0 ? debounceSeconds
                                                                            : 0.0) {}

    void feed(const RawRecord& record, std::vector<ControlEvent>& out) override {
        switch (record.kind) {
        case RawRecord::Kind::GpioEdge:
            if (!std::isfinite(record.time)) {
                problems_.add(name_ + ": edge without a valid time (ignored)");
                return;
            }
            edge(record.time, record.active, out);
            return;
        default:
            feedOtherRecord(*this, record, out, problems_, name_, "a GPIO");
            return;
        }
    }

    void tick(double now, std::vector<ControlEvent>& out) override {
        if (pending_ && quietAt(now)) {
            const bool level = *pending_;
            pending_.reset();
            send(level, now, out);
        }
    }

    void reset(double now, std::vector<ControlEvent>& out) override {
        pending_.reset();
        lastEdge_.reset();
        send(false, now, out);
    }

    std::vector<std::string> takeProblems() override { return problems_.take(); }

  private:
    void edge(double t, bool active, std::vector<ControlEvent>& out) {
        tick(t, out); // a bounce that settled before this edge counts first
        if (!pending_ && quietAt(t)) {
            send(active, t, out);
        } else {
            pending_ = active;
        }
        lastEdge_ = t;
    }

    // No edge within the debounce time before `t` (time running backwards counts as not quiet).
    [[nodiscard]] bool quietAt(double t) const { return !lastEdge_ || t - *lastEdge_ >= debounce_; }

    void send(bool level, double t, std::vector<ControlEvent>& out) {
        if (level != sent_) {
            sent_ = level;
            out.push_back({level ? ControlEvent::Kind::Press : ControlEvent::Kind::Release, t,
                           name_, 0, 0.0});
        }
    }

    std::string name_;
    double debounce_;
    ProblemLog problems_;
    std::optional<double> lastEdge_;
    std::optional<bool> pending_; // the level the line bounced to, not yet settled
    bool sent_ = false;
};

} // namespace

std::unique_ptr<Decoder> makeGpioLineDecoder(const DeviceSpec& spec) {
    return std::make_unique<GpioLineDecoder>(spec.name, spec.debounceSeconds);
}

} // namespace steerseg::platform::input
