#include "model/speed_kind.hpp"
#include "script/script_verbs.hpp"
#include "script/script_words.hpp"

namespace steerseg::script::detail {

namespace {

using workflow::Action;

StepKind actionStep(Action action) {
    return ActionStep{std::move(action)};
}

template <typename A> Handler plain(const char* usage) {
    return [usage](Words& w) {
        w.finish(usage);
        return actionStep(A{});
    };
}

StepKind load(Words& w) {
    std::string path = w.text("a scan path ($SCAN, builtin:sample, ...)");
    if (path.empty()) {
        throw LineError("the scan path is empty");
    }
    detail::checkVariables(path);
    w.finish("load PATH");
    return actionStep(workflow::LoadScan{path});
}

StepKind probe(Words& w) {
    workflow::Probe p;
    p.voxel = voxelWords(w);
    if (!w.empty()) {
        p.radiusMm = w.number("the probe radius (mm)", 0.1, 1000.0);
    }
    w.finish("probe I J K [RADIUS_MM]");
    return actionStep(p);
}

template <typename Sphere> Handler sphere(const char* usage) {
    return [usage](Words& w) {
        Sphere s;
        s.voxel = voxelWords(w);
        if (!w.empty()) {
            s.radius = w.number("the radius (voxels)", 0.1, 10000.0);
        }
        w.finish(usage);
        return actionStep(s);
    };
}

StepKind eraseMode(Words& w) {
    const std::string on = w.text("on or off");
    w.finish("erase_mode on|off");
    if (on != "on" && on != "off") {
        throw LineError("erase_mode '" + on + "': give on or off");
    }
    return actionStep(workflow::SetEraseMode{on == "on"});
}

StepKind speedVerb(Words& w) {
    const std::string name = w.text("threshold, edge or classify");
    w.finish("speed threshold|edge|classify");
    const std::optional<model::SpeedKind> kind = model::parseSpeedKind(name);
    if (!kind) {
        throw LineError("speed '" + name + "': give threshold, edge or classify");
    }
    return actionStep(workflow::SetSpeed{*kind});
}

// An outside example for the classify speed, sized as a probe.
StepKind outside(Words& w) {
    workflow::MarkOutside m;
    m.voxel = voxelWords(w);
    if (!w.empty()) {
        m.radiusMm = w.number("the example's radius (mm)", 0.1, 1000.0);
    }
    w.finish("outside I J K [RADIUS_MM]");
    return actionStep(m);
}

StepKind outsideMode(Words& w) {
    const std::string on = w.text("on or off");
    w.finish("outside_mode on|off");
    if (on != "on" && on != "off") {
        throw LineError("outside_mode '" + on + "': give on or off");
    }
    return actionStep(workflow::SetOutsideMode{on == "on"});
}

StepKind autosave(Words& w) {
    const std::string answer = w.text("resume or discard");
    w.finish("autosave resume|discard");
    if (answer != "resume" && answer != "discard") {
        throw LineError("autosave '" + answer + "': give resume or discard");
    }
    return AutosaveStep{answer == "resume"};
}

StepKind set(Words& w) {
    const workflow::Param param = paramWord(w);
    const double value = w.number("the value", -kMaxValue, kMaxValue);
    w.finish("set T|eps|alpha|radius VALUE");
    return actionStep(workflow::SetParam{param, value});
}

StepKind nudge(Words& w) {
    if (w.accept("selected")) {
        const double steps = w.number("the steps", -10000.0, 10000.0);
        w.finish("nudge selected STEPS");
        return actionStep(workflow::NudgeSelected{steps});
    }
    const workflow::Param param = paramWord(w);
    const double steps = w.number("the steps", -10000.0, 10000.0);
    w.finish("nudge T|eps|alpha|radius|selected STEPS");
    return actionStep(workflow::NudgeParam{param, steps});
}

StepKind select(Words& w) {
    const workflow::Param param = paramWord(w);
    w.finish("select T|eps|alpha|radius");
    return actionStep(workflow::SelectParam{param});
}

StepKind cycle(Words& w) {
    int delta = 1;
    if (!w.empty()) {
        delta = static_cast<int>(w.integer("the step", -10, 10));
    }
    w.finish("cycle [STEP]");
    return actionStep(workflow::CycleParam{delta});
}

StepKind preset(Words& w) {
    std::string name = w.text("a preset name");
    w.finish("preset NAME (quote a name with blanks)");
    if (name.empty()) {
        throw LineError("the preset name is empty");
    }
    return actionStep(workflow::ApplyPreset{name});
}

StepKind window(Words& w) {
    const double level = w.number("the level", -kMaxValue, kMaxValue);
    const double width = w.number("the width", 1e-6, kMaxValue);
    w.finish("window LEVEL WIDTH");
    return actionStep(workflow::SetWindow{level, width});
}

StepKind rotate(Words& w) {
    const double yaw = w.number("the yaw (degrees)", -3600.0, 3600.0);
    const double pitch = w.number("the pitch (degrees)", -3600.0, 3600.0);
    w.finish("rotate YAW PITCH");
    return actionStep(workflow::RotateView{yaw, pitch});
}

StepKind zoom(Words& w) {
    const double factor = w.number("the zoom factor", 1e-3, 1e3);
    w.finish("zoom FACTOR");
    return actionStep(workflow::ZoomView{factor});
}

StepKind page(Words& w) {
    const workflow::SliceAxis axis = axisWord(w);
    const int delta = static_cast<int>(w.integer("the slices", -100000, 100000));
    w.finish("page AXIS SLICES");
    return actionStep(workflow::PageSlice{axis, delta});
}

StepKind slice(Words& w) {
    const workflow::SliceAxis axis = axisWord(w);
    const int index = static_cast<int>(w.integer("the slice index", -1, 100000));
    w.finish("slice AXIS INDEX");
    return actionStep(workflow::SetSlice{axis, index});
}

StepKind show(Words& w) {
    const workflow::SliceAxis first = axisWord(w);
    const workflow::SliceAxis second = axisWord(w);
    w.finish("show AXIS AXIS");
    return actionStep(workflow::ShowSlices{first, second});
}

StepKind exportMask(Words& w) {
    std::string path;
    if (!w.empty()) {
        path = pathWord(w, "the export path");
    }
    w.finish("export [PATH]");
    return actionStep(workflow::Export{path});
}

StepKind frame(Words& w) {
    std::string path = pathWord(w, "the frame's path (.png)");
    w.finish("frame PATH.png");
    if (!path.ends_with(".png")) {
        throw LineError("frame '" + path + "': the file name must end in .png");
    }
    return FrameStep{path};
}

} // namespace

void addOperatorVerbs(VerbTable& table) {
    table.insert({
        {"load", load},
        {"probe", probe},
        {"seed", sphere<workflow::AddSeed>("seed I J K [RADIUS_VOXELS]")},
        {"erase", sphere<workflow::Erase>("erase I J K [RADIUS_VOXELS]")},
        {"erase_mode", eraseMode},
        {"speed", speedVerb},
        {"outside", outside},
        {"outside_mode", outsideMode},
        {"clear_examples", plain<workflow::ClearExamples>("clear_examples")},
        {"set", set},
        {"nudge", nudge},
        {"select", select},
        {"cycle", cycle},
        {"preset", preset},
        {"window", window},
        {"run", plain<workflow::Run>("run")},
        {"pause", plain<workflow::Pause>("pause")},
        {"toggle", plain<workflow::ToggleRun>("toggle")},
        {"finish", plain<workflow::Finish>("finish")},
        {"resume", plain<workflow::Resume>("resume")},
        {"undo", plain<workflow::Undo>("undo")},
        {"redo", plain<workflow::Redo>("redo")},
        {"restart", plain<workflow::Restart>("restart")},
        {"proceed", plain<workflow::Proceed>("proceed")},
        {"back", plain<workflow::Back>("back")},
        {"dismiss", plain<workflow::Dismiss>("dismiss")},
        {"quit", plain<workflow::Quit>("quit")},
        {"rotate", rotate},
        {"zoom", zoom},
        {"page", page},
        {"slice", slice},
        {"show", show},
        {"export", exportMask},
        {"frame", frame},
        {"autosave", autosave},
    });
}

} // namespace steerseg::script::detail
