#include "config/config_sections.hpp"
#include "config/key_names.hpp"

namespace steerseg::config::detail {

namespace {

// The action that unbinds a default: `z = "none"`.
constexpr std::string_view kUnbound = "none";
constexpr double kMaxSteps = 1000.0;

std::optional<Binding> readBinding(const toml::node& node, const std::string& key,
                                   const BindingCheck& check, bool canRelease, ProblemSink& sink) {
    const auto checkAction = [&check](std::string_view action) -> std::string {
        if (action.empty()) {
            return "the action must not be empty";
        }
        if (action == kUnbound || check(action)) {
            return "";
        }
        return "\"" + std::string(action) + "\" is not an action a control can do";
    };
    if (node.is_string()) {
        auto action = readText(node, key, checkAction, sink);
        return action ? std::optional<Binding>(Binding{*action, 1.0, ""}) : std::nullopt;
    }
    const toml::table* table = node.as_table();
    if (table == nullptr) {
        sink.add(node.source(), key,
                 canRelease ? "expected an action name or { action = \"...\", steps = N, "
                              "release = \"...\" }"
                            : "expected an action name or { action = \"...\", steps = N }");
        return std::nullopt;
    }
    TableReader t(*table, key, sink);
    const auto action = t.text("action", checkAction);
    if (!t.has("action")) {
        sink.add(table->source(), key, "has no action");
    }
    const auto steps = t.number("steps", {-kMaxSteps, kMaxSteps});
    if (steps && *steps == 0.0) {
        t.problem("steps", "must not be 0");
    }
    // What letting go does: only a button or pedal has a release (a key repeats instead).
    std::optional<std::string> release;
    if (canRelease) {
        release = t.text("release", [&](std::string_view a) {
            return a == kUnbound ? std::string("\"none\" is not a release action; leave "
                                               "release out")
                                 : checkAction(a);
        });
    }
    t.reportUnknownKeys();
    if (!action || (t.has("steps") && (!steps || *steps == 0.0)) ||
        (t.has("release") && !release)) {
        return std::nullopt;
    }
    return Binding{*action, steps.value_or(1.0), release.value_or("")};
}

void readTable(TableReader& parent, std::string_view name, BindingTable& out,
               bool (*validName)(std::string_view), std::string_view nameRule,
               const BindingCheck& check, bool canRelease) {
    const toml::table* table = parent.table(name);
    if (table == nullptr) {
        return;
    }
    const std::string prefix = parent.path(name);
    for (auto&& [key, node] : *table) {
        const std::string path = keyPath(prefix, key.str());
        if (!validName(key.str())) {
            parent.sink().add(key.source(), path, std::string(nameRule));
            continue;
        }
        if (auto binding = readBinding(node, path, check, canRelease, parent.sink())) {
            if (binding->action == kUnbound) {
                out.erase(std::string(key.str()));
            } else {
                out[std::string(key.str())] = std::move(*binding);
            }
        }
    }
}

} // namespace

void readBindings(TableReader& t, BindingsConfig& bindings, const BindingCheck& check) {
    readTable(t, "keys", bindings.keys, isKeyName,
              "not a key name: a-z, 0-9, f1-f12, space, enter, escape, backspace, tab, left, "
              "right, up, down, pageup, pagedown, plus, minus, delete, home, end, optionally "
              "after ctrl+, shift+ or ctrl+shift+",
              check, false);
    readTable(t, "knobs", bindings.knobs, isControlName,
              "not a control name: 1 to 32 of a-z, 0-9 and _", check, false);
    readTable(t, "buttons", bindings.buttons, isControlName,
              "not a control name: 1 to 32 of a-z, 0-9 and _", check, true);
    t.reportUnknownKeys();
}

} // namespace steerseg::config::detail
