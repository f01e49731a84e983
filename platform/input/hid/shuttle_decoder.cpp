// Contour ShuttleXpress (0b33:0020) and ShuttlePRO v2 (0b33:0030). Both send the same 5-byte
// input report without a report id: byte 0 the shuttle ring (int8, -7..7, 0 at rest), byte 1
// the jog wheel (a uint8 counter that wraps), byte 2 unused, bytes 3-4 the buttons as a
// little-endian bit mask. The PRO v2's fifteen buttons are bits 0..14 (bit 0 = button1); the
// ShuttleXpress's five are bits 4..8, numbered button1..button5 from the left as printed on the
// device, so a site's bindings read like the hardware. Any other product id is numbered by bit.
#include "platform/input/decoder_records.hpp"
#include "platform/input/decoders.hpp"
#include "platform/input/problem_log.hpp"

#include <cstdint>
#include <optional>
#include <string_view>

namespace steerseg::platform::input {

namespace {

constexpr std::size_t kReportBytes = 5;
constexpr int kRingMax = 7;
constexpr unsigned kButtonBits = 15;
constexpr std::uint16_t kShuttleXpressProduct = 0x0020;
constexpr unsigned kXpressFirstBit = 4;
constexpr unsigned kXpressButtons = 5;

class ShuttleDecoder final : public Decoder {
  public:
    ShuttleDecoder(std::string name, unsigned firstBit, unsigned validMask)
        : name_(std::move(name)), firstBit_(firstBit), validMask_(validMask) {}

    void feed(const RawRecord& record, std::vector<ControlEvent>& out) override {
        switch (record.kind) {
        case RawRecord::Kind::HidReport:
            report(record, out);
            return;
        case RawRecord::Kind::HidDescriptor:
            return; // the layout is fixed; the descriptor says nothing new
        default:
            feedOtherRecord(*this, record, out, problems_, name_, "a HID");
            return;
        }
    }

    void tick(double /*now*/, std::vector<ControlEvent>& /*out*/) override {}

    void reset(double now, std::vector<ControlEvent>& out) override {
        releaseButtons(0, now, out);
        if (ring_ != 0) {
            ring_ = 0;
            out.push_back({ControlEvent::Kind::Position, now, name_ + "_ring", 0, 0.0});
        }
        jog_.reset(); // after a replug the counter starts wherever the device says
    }

    std::vector<std::string> takeProblems() override { return problems_.take(); }

  private:
    void report(const RawRecord& record, std::vector<ControlEvent>& out) {
        const std::vector<std::uint8_t>& b = record.bytes;
        if (b.size() != kReportBytes) {
            problems_.add(name_ + ": report of " + std::to_string(b.size()) + " bytes, expected " +
                          std::to_string(kReportBytes));
            return;
        }
        const int ring = static_cast<std::int8_t>(b[0]);
        const unsigned buttons = b[3] | (unsigned{b[4]} << 8);
        if (ring < -kRingMax || ring > kRingMax) {
            problems_.add(name_ + ": ring position " + std::to_string(ring) +
                          " outside -7..7 (report dropped)");
            return;
        }
        if ((buttons & ~validMask_) != 0) {
            problems_.add(name_ + ": button bits 0x" + hex(buttons & ~validMask_) +
                          " set, no such button (report dropped)");
            return;
        }
        const double t = record.time;
        if (jog_) {
            // The counter's 8-bit difference as a signed step count: 255 -> 0 is +1.
            const int steps = static_cast<std::int8_t>(static_cast<std::uint8_t>(b[1] - *jog_));
            if (steps != 0) {
                out.push_back({ControlEvent::Kind::Step, t, name_ + "_jog", steps, 0.0});
            }
        }
        jog_ = b[1];
        if (ring != ring_) {
            ring_ = ring;
            out.push_back({ControlEvent::Kind::Position, t, name_ + "_ring", 0,
                           static_cast<double>(ring) / kRingMax});
        }
        for (unsigned bit = 0; bit < kButtonBits; ++bit) {
            const unsigned mask = 1U << bit;
            if ((buttons & mask) != 0 && (buttons_ & mask) == 0) {
                out.push_back({ControlEvent::Kind::Press, t, button(bit), 0, 0.0});
            }
        }
        releaseButtons(buttons, t, out);
        buttons_ = buttons;
    }

    // Releases the held buttons that are not in `still`.
    void releaseButtons(unsigned still, double t, std::vector<ControlEvent>& out) {
        for (unsigned bit = 0; bit < kButtonBits; ++bit) {
            const unsigned mask = 1U << bit;
            if ((buttons_ & mask) != 0 && (still & mask) == 0) {
                out.push_back({ControlEvent::Kind::Release, t, button(bit), 0, 0.0});
            }
        }
        buttons_ &= still;
    }

    [[nodiscard]] std::string button(unsigned bit) const {
        return name_ + "_button" + std::to_string(bit - firstBit_ + 1);
    }

    static std::string hex(unsigned value) {
        constexpr std::string_view kDigits = "0123456789abcdef";
        std::string text;
        do {
            text.insert(text.begin(), kDigits[value & 0xFU]);
            value >>= 4U;
        } while (value != 0);
        return text;
    }

    std::string name_;
    unsigned firstBit_;  // the bit of button1
    unsigned validMask_; // the bits the model has buttons on
    ProblemLog problems_;
    std::optional<std::uint8_t> jog_; // the last counter value; none until the first report
    int ring_ = 0;
    unsigned buttons_ = 0;
};

} // namespace

std::unique_ptr<Decoder> makeShuttleDecoder(const DeviceSpec& spec) {
    if (spec.productId == kShuttleXpressProduct) {
        return std::make_unique<ShuttleDecoder>(spec.name, kXpressFirstBit,
                                                ((1U << kXpressButtons) - 1U) << kXpressFirstBit);
    }
    return std::make_unique<ShuttleDecoder>(spec.name, 0U, (1U << kButtonBits) - 1U);
}

} // namespace steerseg::platform::input
