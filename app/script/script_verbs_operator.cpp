#include "model/speed_kind.hpp"
#include "script/script_verbs.hpp"
#include "script/script_words.hpp"

#include <array>
#include <optional>
#include <string>

namespace steerseg::script::detail {

namespace {

using model::Action;

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
    return actionStep(model::LoadScan{path});
}

StepKind probe(Words& w) {
    model::Probe p;
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

// A correction as `segment --click` gives it (docs/steering.md): + adds, - removes.
StepKind click(Words& w) {
    model::Correct c;
    c.voxel = voxelWords(w);
    const std::string sign = w.text("+ or -");
    if (sign != "+" && sign != "-") {
        throw LineError("click '" + sign + "': give + (add) or - (remove)");
    }
    c.positive = sign == "+";
    if (!w.empty()) {
        c.radius = w.number("the radius (voxels)", 0.1, 10000.0);
    }
    w.finish("click I J K +|- [RADIUS_VOXELS]");
    return actionStep(c);
}

// A painted stroke through the given voxels: what a drag on a slice sends (docs/ui.md).
StepKind stroke(Words& w) {
    const char* usage = "stroke add|erase|outside RADIUS|brush I J K [I J K ...]";
    const std::string name = w.text("add, erase or outside");
    const std::optional<model::StrokeMode> mode = model::strokeModeFromName(name);
    if (!mode) {
        throw LineError("stroke '" + name +
                        "': give add, erase or outside (usage: " + std::string(usage) + ")");
    }
    model::PaintStroke p;
    p.mode = *mode;
    if (!w.accept("brush")) {
        p.radius = w.number("the radius (voxels) or brush", 0.1, 10000.0);
    }
    do {
        if (p.points.size() == model::kMaxStrokePoints) {
            throw LineError("a stroke of more than " + std::to_string(model::kMaxStrokePoints) +
                            " points: split it into several");
        }
        p.points.push_back(voxelWords(w));
    } while (!w.empty());
    w.finish(usage);
    return actionStep(std::move(p));
}

StepKind eraseMode(Words& w) {
    const std::string on = w.text("on or off");
    w.finish("erase_mode on|off");
    if (on != "on" && on != "off") {
        throw LineError("erase_mode '" + on + "': give on or off");
    }
    return actionStep(model::SetEraseMode{on == "on"});
}

StepKind speedVerb(Words& w) {
    const std::string name = w.text("threshold, edge or classify");
    w.finish("speed threshold|edge|classify");
    const std::optional<model::SpeedKind> kind = model::parseSpeedKind(name);
    if (!kind) {
        throw LineError("speed '" + name + "': give threshold, edge or classify");
    }
    return actionStep(model::SetSpeed{*kind});
}

// An outside example for the classify speed, sized as a probe.
StepKind outside(Words& w) {
    model::MarkOutside m;
    m.voxel = voxelWords(w);
    if (!w.empty()) {
        m.radiusMm = w.number("the example's radius (mm)", 0.1, 1000.0);
    }
    w.finish("outside I J K [RADIUS_MM]");
    return actionStep(m);
}

// The box's two corners (voxel indices, model::Box), or `box clear`. Whether it fits the scan
// is the workflow's to say, as for a sphere.
StepKind box(Words& w) {
    static constexpr const char* kUsage = "box I0 J0 K0 I1 J1 K1 | box clear";
    if (w.accept("clear")) {
        w.finish(kUsage);
        return actionStep(model::ClearBox{});
    }
    model::SetBox b;
    static constexpr std::array<const char*, 6> kNames{"the box's i0", "the box's j0",
                                                       "the box's k0", "the box's i1",
                                                       "the box's j1", "the box's k1"};
    for (int n = 0; n < 6; ++n) {
        const auto v = static_cast<int>(w.integer(kNames[static_cast<std::size_t>(n)],
                                                  static_cast<long long>(-kMaxCoordinate),
                                                  static_cast<long long>(kMaxCoordinate)));
        (n < 3 ? b.box.lo : b.box.hi)[n % 3] = v;
    }
    w.finish(kUsage);
    return actionStep(b);
}

StepKind outsideMode(Words& w) {
    const std::string on = w.text("on or off");
    w.finish("outside_mode on|off");
    if (on != "on" && on != "off") {
        throw LineError("outside_mode '" + on + "': give on or off");
    }
    return actionStep(model::SetOutsideMode{on == "on"});
}

// Box mode (docs/ui.md): a drag on a slice draws the box; the script's `touch` events draw it.
StepKind boxMode(Words& w) {
    const std::string on = w.text("on or off");
    w.finish("box_mode on|off");
    if (on != "on" && on != "off") {
        throw LineError("box_mode '" + on + "': give on or off");
    }
    return actionStep(model::SetBoxMode{on == "on", std::nullopt});
}

// The session's structures (docs/structures.md); a name with blanks goes in double quotes.
StepKind structure(Words& w) {
    constexpr const char* kUsage = "structure add|select|show|hide|delete NAME, structure rename "
                                   "NAME NEW_NAME, structure colour NAME R G B (0..1)";
    const std::string word = w.text("add, select, rename, colour, show, hide or delete");
    const std::optional<model::StructureOp> op =
        word == "colour" ? model::StructureOp::Recolour : model::structureOpFromName(word);
    if (!op) {
        throw LineError("structure '" + word + "': " + kUsage);
    }
    model::EditStructure e{*op, w.text("the structure's name"), {}, glm::dvec3(0.0)};
    if (*op == model::StructureOp::Rename) {
        e.to = w.text("the new name");
    } else if (*op == model::StructureOp::Recolour) {
        e.colour.r = w.number("red", 0.0, 1.0);
        e.colour.g = w.number("green", 0.0, 1.0);
        e.colour.b = w.number("blue", 0.0, 1.0);
    }
    w.finish(kUsage);
    return actionStep(e);
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
    const model::Param param = paramWord(w);
    const double value = w.number("the value", -kMaxValue, kMaxValue);
    w.finish("set T|eps|alpha|radius VALUE");
    return actionStep(model::SetParam{param, value});
}

StepKind nudge(Words& w) {
    if (w.accept("selected")) {
        const double steps = w.number("the steps", -10000.0, 10000.0);
        w.finish("nudge selected STEPS");
        return actionStep(model::NudgeSelected{steps});
    }
    const model::Param param = paramWord(w);
    const double steps = w.number("the steps", -10000.0, 10000.0);
    w.finish("nudge T|eps|alpha|radius|selected STEPS");
    return actionStep(model::NudgeParam{param, steps});
}

StepKind select(Words& w) {
    const model::Param param = paramWord(w);
    w.finish("select T|eps|alpha|radius");
    return actionStep(model::SelectParam{param});
}

StepKind cycle(Words& w) {
    int delta = 1;
    if (!w.empty()) {
        delta = static_cast<int>(w.integer("the step", -10, 10));
    }
    w.finish("cycle [STEP]");
    return actionStep(model::CycleParam{delta});
}

StepKind preset(Words& w) {
    std::string name = w.text("a preset name");
    w.finish("preset NAME (quote a name with blanks)");
    if (name.empty()) {
        throw LineError("the preset name is empty");
    }
    return actionStep(model::ApplyPreset{name});
}

StepKind window(Words& w) {
    const double level = w.number("the level", -kMaxValue, kMaxValue);
    const double width = w.number("the width", 1e-6, kMaxValue);
    w.finish("window LEVEL WIDTH");
    return actionStep(model::SetWindow{level, width});
}

StepKind rotate(Words& w) {
    const double yaw = w.number("the yaw (degrees)", -3600.0, 3600.0);
    const double pitch = w.number("the pitch (degrees)", -3600.0, 3600.0);
    w.finish("rotate YAW PITCH");
    return actionStep(model::RotateView{yaw, pitch});
}

StepKind zoom(Words& w) {
    const double factor = w.number("the zoom factor", 1e-3, 1e3);
    w.finish("zoom FACTOR");
    return actionStep(model::ZoomView{factor});
}

StepKind page(Words& w) {
    const model::SliceAxis axis = axisWord(w);
    const int delta = static_cast<int>(w.integer("the slices", -100000, 100000));
    w.finish("page AXIS SLICES");
    return actionStep(model::PageSlice{axis, delta});
}

StepKind slice(Words& w) {
    const model::SliceAxis axis = axisWord(w);
    const int index = static_cast<int>(w.integer("the slice index", -1, 100000));
    w.finish("slice AXIS INDEX");
    return actionStep(model::SetSlice{axis, index});
}

StepKind show(Words& w) {
    const model::SliceAxis first = axisWord(w);
    const model::SliceAxis second = axisWord(w);
    w.finish("show AXIS AXIS");
    return actionStep(model::ShowSlices{first, second});
}

StepKind exportMask(Words& w) {
    std::string path;
    if (!w.empty()) {
        path = pathWord(w, "the export path");
    }
    w.finish("export [PATH]");
    return actionStep(model::Export{path});
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
        {"seed", sphere<model::AddSeed>("seed I J K [RADIUS_VOXELS]")},
        {"erase", sphere<model::Erase>("erase I J K [RADIUS_VOXELS]")},
        {"erase_mode", eraseMode},
        {"click", click},
        {"stroke", stroke},
        {"speed", speedVerb},
        {"outside", outside},
        {"outside_mode", outsideMode},
        {"box", box},
        {"box_mode", boxMode},
        {"structure", structure},
        {"clear_examples", plain<model::ClearExamples>("clear_examples")},
        {"set", set},
        {"nudge", nudge},
        {"select", select},
        {"cycle", cycle},
        {"preset", preset},
        {"window", window},
        {"run", plain<model::Run>("run")},
        {"pause", plain<model::Pause>("pause")},
        {"toggle", plain<model::ToggleRun>("toggle")},
        {"finish", plain<model::Finish>("finish")},
        {"resume", plain<model::Resume>("resume")},
        {"undo", plain<model::Undo>("undo")},
        {"redo", plain<model::Redo>("redo")},
        {"restart", plain<model::Restart>("restart")},
        {"proceed", plain<model::Proceed>("proceed")},
        {"back", plain<model::Back>("back")},
        {"dismiss", plain<model::Dismiss>("dismiss")},
        {"acknowledge_audit", plain<model::AcknowledgeAudit>("acknowledge_audit")},
        {"quit", plain<model::Quit>("quit")},
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
