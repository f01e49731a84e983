// A HID radial controller (the Surface Dial's kind): a System Multi-Axis Controller collection
// (Generic Desktop 0x0E) holding a relative Dial (0x37), or a Wheel (0x38) where there is no
// Dial, and a button (Button page). The fields are found by parsing the report descriptor, which
// the source sends first, so a controller with another layout needs no new code.
#include "platform/input/decoder_records.hpp"
#include "platform/input/decoders.hpp"
#include "platform/input/hid/field_extract.hpp"
#include "platform/input/hid/report_descriptor.hpp"
#include "platform/input/problem_log.hpp"

#include <optional>

namespace steerseg::platform::input {

namespace {

constexpr std::uint16_t kGenericDesktop = 0x01;
constexpr std::uint16_t kMultiAxisController = 0x0E;
constexpr std::uint16_t kDial = 0x37;
constexpr std::uint16_t kWheel = 0x38;
constexpr std::uint16_t kButtonPage = 0x09;

struct Layout {
    hid::ReportDescriptor descriptor;
    hid::HidField turn;
    std::optional<hid::HidField> press;
};

bool readable(const hid::HidField& f) {
    return !f.constant && f.variable && f.bitSize >= 1 && f.bitSize <= 32;
}

// The multi-axis controller collection enclosing `f`, or -1. Parents precede their children,
// so the walk is at most the nesting depth the parser allows.
int controllerOf(const hid::ReportDescriptor& d, const hid::HidField& f) {
    for (int c = f.collection; c >= 0; c = d.collections[static_cast<std::size_t>(c)].parent) {
        const hid::HidCollection& col = d.collections[static_cast<std::size_t>(c)];
        if (col.usagePage == kGenericDesktop && col.usage == kMultiAxisController) {
            return c;
        }
    }
    return -1;
}

// The first relative Dial inside a multi-axis controller (else the first such Wheel) and that
// controller's button. Linear in the fields, so a hostile descriptor stays cheap.
std::optional<Layout> findLayout(hid::ReportDescriptor descriptor, std::string& problem) {
    const hid::HidField* turn = nullptr;
    int controller = -1;
    for (const std::uint16_t wanted : {kDial, kWheel}) {
        for (const hid::HidField& f : descriptor.inputs) {
            if (!turn && readable(f) && f.relative && f.usagePage == kGenericDesktop &&
                f.usage == wanted) {
                controller = controllerOf(descriptor, f);
                turn = controller >= 0 ? &f : nullptr;
            }
        }
    }
    if (!turn) {
        problem = "report descriptor has no relative Dial or Wheel in a System Multi-Axis "
                  "Controller collection";
        return std::nullopt;
    }
    const hid::HidField* press = nullptr;
    for (const hid::HidField& f : descriptor.inputs) {
        // The primary button (usage 1) where there are several.
        if (readable(f) && f.usagePage == kButtonPage &&
            (!press || (f.usage == 1 && press->usage != 1)) && descriptor.within(f, controller)) {
            press = &f;
        }
    }
    Layout layout{{}, *turn, press ? std::optional(*press) : std::nullopt};
    layout.descriptor = std::move(descriptor);
    return layout;
}

class RadialDecoder final : public Decoder {
  public:
    explicit RadialDecoder(std::string name) : name_(std::move(name)) {}

    void feed(const RawRecord& record, std::vector<ControlEvent>& out) override {
        switch (record.kind) {
        case RawRecord::Kind::HidDescriptor:
            descriptor(record, out);
            return;
        case RawRecord::Kind::HidReport:
            report(record, out);
            return;
        default:
            feedOtherRecord(*this, record, out, problems_, name_, "a HID");
            return;
        }
    }

    void tick(double /*now*/, std::vector<ControlEvent>& /*out*/) override {}

    void reset(double now, std::vector<ControlEvent>& out) override {
        if (pressed_) {
            pressed_ = false;
            out.push_back({ControlEvent::Kind::Release, now, name_ + "_press", 0, 0.0});
        }
    }

    std::vector<std::string> takeProblems() override { return problems_.take(); }

  private:
    void descriptor(const RawRecord& record, std::vector<ControlEvent>& out) {
        std::string problem;
        std::optional<hid::ReportDescriptor> parsed =
            hid::parseReportDescriptor(record.bytes, problem);
        std::optional<Layout> layout;
        if (parsed) {
            layout = findLayout(std::move(*parsed), problem);
        }
        reset(record.time, out); // a new layout: what the old one held is over
        layout_ = std::move(layout);
        if (!layout_) {
            problems_.add(name_ + ": " + problem + " (reports ignored until a usable one)");
        }
    }

    void report(const RawRecord& record, std::vector<ControlEvent>& out) {
        if (!layout_) {
            problems_.add(name_ + ": report before a usable report descriptor (ignored)");
            return;
        }
        const std::vector<std::uint8_t>& b = record.bytes;
        const hid::ReportDescriptor& d = layout_->descriptor;
        if (b.empty()) {
            problems_.add(name_ + ": empty report");
            return;
        }
        const std::uint8_t id = d.usesReportIds ? b[0] : 0;
        const std::size_t expected = d.inputReportBytes(id);
        if (expected == 0) {
            problems_.add(name_ + ": report id " + std::to_string(id) +
                          " not in the descriptor (ignored)");
            return;
        }
        if (b.size() != expected) {
            problems_.add(name_ + ": report " + std::to_string(id) + " of " +
                          std::to_string(b.size()) + " bytes, expected " +
                          std::to_string(expected));
            return;
        }
        const std::span<const std::uint8_t> data = std::span(b).subspan(d.usesReportIds ? 1 : 0);
        const hid::HidField& turn = layout_->turn;
        if (turn.reportId == id) {
            const auto v = hid::extractField(data, turn.bitOffset, turn.bitSize, turn.isSigned);
            if (v && *v != 0) {
                out.push_back({ControlEvent::Kind::Step, record.time, name_ + "_turn",
                               static_cast<int>(*v), 0.0});
            }
        }
        if (layout_->press && layout_->press->reportId == id) {
            const hid::HidField& p = *layout_->press;
            const auto v = hid::extractField(data, p.bitOffset, p.bitSize, p.isSigned);
            const bool down = v && *v != 0;
            if (down != pressed_) {
                pressed_ = down;
                out.push_back({down ? ControlEvent::Kind::Press : ControlEvent::Kind::Release,
                               record.time, name_ + "_press", 0, 0.0});
            }
        }
    }

    std::string name_;
    ProblemLog problems_;
    std::optional<Layout> layout_;
    bool pressed_ = false;
};

} // namespace

std::unique_ptr<Decoder> makeRadialDecoder(const DeviceSpec& spec) {
    return std::make_unique<RadialDecoder>(spec.name);
}

} // namespace steerseg::platform::input
