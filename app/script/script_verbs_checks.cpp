#include "model/speed_kind.hpp"
#include "script/script_verbs.hpp"
#include "script/script_words.hpp"

#include <algorithm>

namespace steerseg::script::detail {

namespace {

using Op = Condition::Op;

bool isStatusField(const std::string& word) {
    const auto& fields = statusFields();
    return std::find(fields.begin(), fields.end(), word) != fields.end();
}

std::string knownFields() {
    std::string known;
    for (const std::string_view f : statusFields()) {
        known += (known.empty() ? "" : ", ") + std::string(f);
    }
    return known;
}

// FIELD OP VALUE after the field's name, as `expect` and `wait until` share it.
void fieldComparison(Words& w, const std::string& field, Condition& c) {
    c.kind = Condition::Compare;
    c.field = field;
    c.op = opWord(w);
    c.value = w.number("the value", -kMaxValue, kMaxValue);
}

model::SpeedKind speedWord(Words& w) {
    const std::string name = w.text("threshold, edge or classify");
    const std::optional<model::SpeedKind> kind = model::parseSpeedKind(name);
    if (!kind) {
        throw LineError("speed '" + name + "': give threshold, edge or classify");
    }
    return *kind;
}

StepKind wait(Words& w) {
    const char* usage =
        "wait converged|loaded|state NAME|speed NAME|iterations N|until FIELD OP VALUE|seconds S "
        "[timeout S]";
    const std::string what = w.text("what to wait for (converged, loaded, state, speed, "
                                    "iterations, until, seconds)");
    WaitStep step;
    if (what == "converged") {
        step.condition.kind = Condition::Converged;
    } else if (what == "loaded") {
        step.condition.kind = Condition::Loaded;
    } else if (what == "state") {
        step.condition.kind = Condition::State;
        step.condition.state = stateWord(w);
    } else if (what == "speed") {
        step.condition.kind = Condition::Speed;
        step.condition.speed = speedWord(w);
    } else if (what == "iterations") {
        step.condition.kind = Condition::Iterations;
        step.condition.count = w.integer("the iterations", 1, 100000000);
    } else if (what == "until") {
        // A field reaching a value, whatever changes it: input from outside the script (a
        // device, an X server's injected events) as well as the script's own steps.
        const std::string field = w.text("the field to wait for");
        if (!isStatusField(field)) {
            throw LineError("wait until '" + field + "': not a field (" + knownFields() + ")");
        }
        fieldComparison(w, field, step.condition);
    } else if (what == "seconds") {
        step.condition.kind = Condition::Seconds;
        step.condition.value = w.number("the seconds", 0.0, kMaxSeconds);
        w.finish("wait seconds S");
        return step;
    } else {
        throw LineError("wait '" + what + "': not a condition (usage: " + usage + ")");
    }
    step.timeoutSeconds = timeoutWords(w);
    w.finish(usage);
    return step;
}

StepKind expect(Words& w) {
    const char* usage = "expect state NAME | speed NAME | loaded | converged | FIELD OP VALUE | "
                        "message contains TEXT | exported contains TEXT";
    const std::string what = w.text("what to check");
    ExpectStep step;
    Condition& c = step.condition;
    if (what == "state") {
        c.kind = Condition::State;
        c.state = stateWord(w);
    } else if (what == "speed") {
        c.kind = Condition::Speed;
        c.speed = speedWord(w);
    } else if (what == "loaded") {
        c.kind = Condition::Loaded;
    } else if (what == "converged" && w.empty()) {
        c.kind = Condition::Converged;
    } else if (what == "message" || what == "exported") {
        c.kind = what == "message" ? Condition::MessageHas : Condition::ExportedHas;
        if (!w.accept("contains")) {
            throw LineError("expect " + what + ": write 'expect " + what + " contains TEXT'");
        }
        c.text = w.text("the text");
    } else {
        if (!isStatusField(what)) {
            throw LineError("expect '" + what +
                            "': not a check (state, speed, loaded, converged, "
                            "message, exported, or a field: " +
                            knownFields() + ")");
        }
        fieldComparison(w, what, c);
    }
    w.finish(usage);
    return step;
}

StepKind dice(Words& w) {
    const char* usage = "dice MASK REFERENCE [label N] OP VALUE";
    DiceStep step;
    step.mask = pathWord(w, "the mask's path");
    step.reference = pathWord(w, "the reference's path");
    if (w.accept("label")) {
        step.label = static_cast<int>(w.integer("the label", 0, 65535));
    }
    step.op = opWord(w);
    step.value = w.number("the Dice bound", 0.0, 1.0);
    w.finish(usage);
    return step;
}

} // namespace

void addCheckVerbs(VerbTable& table) {
    table.insert({
        {"wait", wait},
        {"expect", expect},
        {"dice", dice},
    });
}

} // namespace steerseg::script::detail
