#include "config/config_sections.hpp"
#include "config/key_names.hpp"

#include <algorithm>

namespace steerseg::config::detail {

namespace {

constexpr std::size_t kMaxDevices = 32; // a console's controls, not a registry
constexpr long long kMaxId = 0xffff;    // USB ids and HID usages are 16 bits

bool isHid(InputDeviceKind kind) {
    return kind == InputDeviceKind::Shuttle || kind == InputDeviceKind::Radial;
}
bool isGpio(InputDeviceKind kind) {
    return kind == InputDeviceKind::GpioInput || kind == InputDeviceKind::GpioLed;
}

// The keys each kind uses; the others are not read, so the table reader reports them as unknown
// (naming the ones the kind knows): a chip given to a shuttle does not pass silently.
bool applies(std::string_view key, InputDeviceKind kind) {
    if (key == "vendor_id" || key == "product_id") {
        return !isGpio(kind);
    }
    if (key == "usage_page" || key == "usage") {
        return isHid(kind);
    }
    if (key == "path") {
        return kind == InputDeviceKind::PowerMate;
    }
    if (key == "chip" || key == "line" || key == "active_low") {
        return isGpio(kind);
    }
    if (key == "debounce_ms") {
        return kind == InputDeviceKind::GpioInput;
    }
    return true;
}

std::string lineProblem(std::string_view text) {
    return text.empty() ? "must name a GPIO line (its name, or its offset as digits)" : "";
}

// Reads one entry into `device`; false when it cannot be used (the problem is reported).
bool readDevice(TableReader& t, InputDeviceConfig& device) {
    bool good = true;
    const auto name = t.text("name", [](std::string_view n) {
        return isControlName(n) ? "" : "must be 1 to 32 of a-z, 0-9 and _";
    });
    if (!t.has("name")) {
        t.sink().add(t.source().source(), t.path("name"), "is missing: every device needs one");
    }
    const auto kind = t.text("kind", [](std::string_view word) {
        return parseInputDeviceKind(word)
                   ? ""
                   : "must be \"shuttle\", \"radial\", \"powermate\", \"gpio_input\" or "
                     "\"gpio_led\"";
    });
    if (!t.has("kind")) {
        t.sink().add(t.source().source(), t.path("kind"), "is missing: every device needs one");
    }
    if (!kind) {
        return false;
    }
    good = name.has_value();
    device.name = name.value_or("");
    device.kind = *parseInputDeviceKind(*kind);
    const InputDeviceKind k = device.kind;
    const auto id = [&](std::string_view key, int& out) {
        if (!applies(key, k)) {
            return;
        }
        if (auto v = t.integer(key, {0, kMaxId})) {
            out = static_cast<int>(*v);
        } else if (t.has(key)) {
            good = false;
        }
    };
    id("vendor_id", device.vendorId);
    id("product_id", device.productId);
    id("usage_page", device.usagePage);
    id("usage", device.usage);
    if (applies("path", k)) {
        if (auto v = t.text("path", [](std::string_view p) {
                return p.empty() || p.front() == '/'
                           ? ""
                           : "must be an input node such as \"/dev/input/event5\", or \"\"";
            })) {
            device.path = *v;
        }
    }
    if (isGpio(k)) {
        if (auto v = t.text("chip", [](std::string_view c) {
                return c.empty() ? "must name a GPIO chip (\"gpiochip0\" or its label)" : "";
            })) {
            device.chip = *v;
        }
        if (auto v = t.text("line", lineProblem)) {
            device.line = *v;
        }
        if (auto v = t.boolean("active_low")) {
            device.activeLow = *v;
        }
        for (const char* required : {"chip", "line"}) {
            if (!t.has(required)) {
                t.sink().add(t.source().source(), t.path(required),
                             "is missing: a " + std::string(inputDeviceKindName(k)) +
                                 " needs a chip and a line");
                good = false;
            }
        }
    }
    if (applies("debounce_ms", k)) {
        if (auto v = t.number("debounce_ms", {0.0, 1000.0})) {
            device.debounceMs = *v;
        }
    }
    // A HID device with neither ids nor usage would match every controller on the bus.
    if (good && isHid(k) && device.vendorId == 0 && device.productId == 0 &&
        device.usagePage == 0 && device.usage == 0) {
        t.problem("kind", "a " + std::string(inputDeviceKindName(k)) +
                              " needs vendor_id/product_id or usage_page/usage to be found");
        good = false;
    }
    if (good && k == InputDeviceKind::PowerMate && device.path.empty() && device.vendorId == 0 &&
        device.productId == 0) {
        t.problem("kind", "a powermate needs a path or vendor_id/product_id to be found");
        good = false;
    }
    return good;
}

} // namespace

void readInputDevices(const toml::array& entries, std::vector<InputDeviceConfig>& devices,
                      ProblemSink& sink) {
    std::vector<InputDeviceConfig> next;
    for (std::size_t i = 0; i < entries.size(); ++i) {
        const toml::node& node = *entries.get(i);
        const std::string prefix = "input.devices[" + std::to_string(i + 1) + "]";
        const toml::table* table = node.as_table();
        if (table == nullptr) {
            sink.add(node.source(), prefix,
                     "expected a table ([[input.devices]]), got something else");
            continue;
        }
        TableReader t(*table, prefix, sink);
        InputDeviceConfig device;
        const bool good = readDevice(t, device);
        t.reportUnknownKeys();
        if (!good) {
            continue;
        }
        if (std::any_of(next.begin(), next.end(),
                        [&](const InputDeviceConfig& d) { return d.name == device.name; })) {
            t.problem("name", "\"" + device.name + "\" is given twice: control names would clash");
            continue;
        }
        if (next.size() >= kMaxDevices) {
            sink.add(table->source(), prefix, "more than 32 devices");
            continue;
        }
        next.push_back(std::move(device));
    }
    devices = std::move(next);
}

} // namespace steerseg::config::detail
