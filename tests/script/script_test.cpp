// Scripted sessions: the parser (every step, every kind of bad line) and the player (timing,
// waits on the status, checks, timeouts), against a recording sink and hand-made statuses.
#include "core/volume.hpp"
#include "exports/mask_writer.hpp"
#include "script/mask_dice.hpp"
#include "script/script.hpp"
#include "script/script_condition.hpp"
#include "script/script_player.hpp"
#include "support/test_data.hpp"

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <gtest/gtest.h>
#include <stdexcept>

namespace steerseg::test {
namespace {

using model::State;
using script::parseScript;
using script::Script;
using script::ScriptError;
using script::ScriptPlayer;
using Kind = platform::InputEvent::Kind;

std::string parseError(const std::string& text, const std::string& name = "s.session") {
    try {
        parseScript(text, name);
    } catch (const ScriptError& e) {
        return e.what();
    }
    return "(parsed)";
}

template <typename T> const T& only(const Script& script) {
    EXPECT_EQ(script.steps.size(), 1U);
    return std::get<T>(script.steps.at(0).kind);
}

template <typename A> A action(const std::string& line) {
    const Script s = parseScript(line, "s");
    return std::get<A>(only<script::ActionStep>(s).action);
}

TEST(ScriptParse, DeviceEvents) {
    const Script s = parseScript("touch down 1 640 400\n"
                                 "touch move 1 650.5 410\n"
                                 "touch up 1 650 410\n"
                                 "tap 10 20\n"
                                 "key ctrl+shift+z\n"
                                 "key_down space\n"
                                 "key_up f12\n"
                                 "wheel 100 200 -3\n",
                                 "s");
    ASSERT_EQ(s.steps.size(), 8U);
    const auto& down = std::get<script::InputStep>(s.steps[0].kind).events;
    ASSERT_EQ(down.size(), 1U);
    EXPECT_EQ(down[0].kind, Kind::PointerDown);
    EXPECT_EQ(down[0].pointer, 1);
    EXPECT_FLOAT_EQ(down[0].x, 640.0F);
    EXPECT_FLOAT_EQ(down[0].y, 400.0F);
    EXPECT_EQ(std::get<script::InputStep>(s.steps[1].kind).events[0].kind, Kind::PointerMove);
    EXPECT_FLOAT_EQ(std::get<script::InputStep>(s.steps[1].kind).events[0].x, 650.5F);
    EXPECT_EQ(std::get<script::InputStep>(s.steps[2].kind).events[0].kind, Kind::PointerUp);
    const auto& tap = std::get<script::InputStep>(s.steps[3].kind).events;
    ASSERT_EQ(tap.size(), 2U);
    EXPECT_EQ(tap[0].kind, Kind::PointerDown);
    EXPECT_EQ(tap[1].kind, Kind::PointerUp);
    const auto& key = std::get<script::InputStep>(s.steps[4].kind).events;
    ASSERT_EQ(key.size(), 2U);
    EXPECT_EQ(key[0].kind, Kind::KeyDown);
    EXPECT_EQ(key[1].kind, Kind::KeyUp);
    EXPECT_EQ(key[0].key, "z");
    EXPECT_TRUE(key[0].ctrl);
    EXPECT_TRUE(key[0].shift);
    EXPECT_EQ(std::get<script::InputStep>(s.steps[5].kind).events[0].key, "space");
    EXPECT_EQ(std::get<script::InputStep>(s.steps[6].kind).events[0].kind, Kind::KeyUp);
    const auto& wheel = std::get<script::InputStep>(s.steps[7].kind).events[0];
    EXPECT_EQ(wheel.kind, Kind::Wheel);
    EXPECT_FLOAT_EQ(wheel.wheel, -3.0F);
}

TEST(ScriptParse, OperatorActions) {
    EXPECT_EQ(action<model::LoadScan>("load builtin:sample").path, "builtin:sample");
    EXPECT_EQ(action<model::LoadScan>("load \"a b/c.nii\"").path, "a b/c.nii");
    EXPECT_EQ(action<model::LoadScan>("load $SCAN").path, "$SCAN");
    const auto probe = action<model::Probe>("probe 80 56 52 6");
    EXPECT_EQ(probe.voxel, glm::dvec3(80, 56, 52));
    EXPECT_DOUBLE_EQ(probe.radiusMm, 6.0);
    EXPECT_DOUBLE_EQ(action<model::Probe>("probe 1 2 3").radiusMm, 0.0)
        << "0: the config's [probe] radius_mm";
    const auto seed = action<model::AddSeed>("seed 1.5 2 3 4");
    EXPECT_EQ(seed.voxel, glm::dvec3(1.5, 2, 3));
    EXPECT_DOUBLE_EQ(seed.radius, 4.0);
    EXPECT_DOUBLE_EQ(action<model::AddSeed>("seed 1 2 3").radius, 0.0); // the brush
    EXPECT_DOUBLE_EQ(action<model::Erase>("erase 4 5 6 2").radius, 2.0);
    const auto click = action<model::Correct>("click 80 56 52 -");
    EXPECT_EQ(click.voxel, glm::dvec3(80, 56, 52));
    EXPECT_FALSE(click.positive);
    EXPECT_DOUBLE_EQ(click.radius, 0.0); // the brush
    EXPECT_TRUE(action<model::Correct>("click 1 2 3 + 2.5").positive);
    EXPECT_DOUBLE_EQ(action<model::Correct>("click 1 2 3 + 2.5").radius, 2.5);
    EXPECT_NE(parseError("click 1 2 3 *").find("give + (add) or - (remove)"), std::string::npos);
    EXPECT_NE(parseError("click 1 2 3").find("+ or -"), std::string::npos);
    EXPECT_TRUE(action<model::SetEraseMode>("erase_mode on").erase);
    EXPECT_FALSE(action<model::SetEraseMode>("erase_mode off").erase);
    const auto set = action<model::SetParam>("set eps 35.5");
    EXPECT_EQ(set.param, model::Param::Eps);
    EXPECT_DOUBLE_EQ(set.value, 35.5);
    EXPECT_EQ(action<model::SetParam>("set T -10").param, model::Param::T);
    EXPECT_EQ(action<model::SetParam>("set alpha 0.9").param, model::Param::Alpha);
    EXPECT_EQ(action<model::SetParam>("set radius 4").param, model::Param::Radius);
    EXPECT_DOUBLE_EQ(action<model::NudgeParam>("nudge alpha -2").steps, -2.0);
    EXPECT_DOUBLE_EQ(action<model::NudgeSelected>("nudge selected 3").steps, 3.0);
    EXPECT_EQ(action<model::SelectParam>("select eps").param, model::Param::Eps);
    EXPECT_EQ(action<model::CycleParam>("cycle").delta, 1);
    EXPECT_EQ(action<model::CycleParam>("cycle -1").delta, -1);
    EXPECT_EQ(action<model::ApplyPreset>("preset \"CT soft tissue\"").name, "CT soft tissue");
    const auto window = action<model::SetWindow>("window 40 400");
    EXPECT_DOUBLE_EQ(window.level, 40.0);
    EXPECT_DOUBLE_EQ(window.width, 400.0);
    action<model::Run>("run");
    action<model::Pause>("pause");
    action<model::ToggleRun>("toggle");
    action<model::Finish>("finish");
    action<model::Resume>("resume");
    action<model::Undo>("undo");
    action<model::Redo>("redo");
    action<model::Restart>("restart");
    action<model::Proceed>("proceed");
    action<model::Back>("back");
    action<model::Dismiss>("dismiss");
    action<model::Quit>("quit");
    const auto rotate = action<model::RotateView>("rotate 30 -10");
    EXPECT_DOUBLE_EQ(rotate.yaw, 30.0);
    EXPECT_DOUBLE_EQ(rotate.pitch, -10.0);
    EXPECT_DOUBLE_EQ(action<model::ZoomView>("zoom 1.5").factor, 1.5);
    const auto page = action<model::PageSlice>("page sagittal -4");
    EXPECT_EQ(page.axis, model::SliceAxis::Sagittal);
    EXPECT_EQ(page.delta, -4);
    const auto slice = action<model::SetSlice>("slice coronal 60");
    EXPECT_EQ(slice.axis, model::SliceAxis::Coronal);
    EXPECT_EQ(slice.index, 60);
    const auto show = action<model::ShowSlices>("show sagittal axial");
    EXPECT_EQ(show.first, model::SliceAxis::Sagittal);
    EXPECT_EQ(show.second, model::SliceAxis::Axial);
    EXPECT_EQ(action<model::Export>("export").path, "");
    EXPECT_EQ(action<model::Export>("export out/mask.nii.gz").path, "out/mask.nii.gz");
}

TEST(ScriptParse, WaitsChecksFramesDice) {
    const Script s = parseScript("wait converged timeout 30\n"
                                 "wait loaded\n"
                                 "wait state paused\n"
                                 "wait iterations 200\n"
                                 "wait seconds 1.5\n"
                                 "expect state review\n"
                                 "expect volume_ml > 1.5\n"
                                 "expect iterations >= 100\n"
                                 "expect message contains \"converged after\"\n"
                                 "expect exported contains .nii.gz\n"
                                 "expect converged\n"
                                 "expect loaded\n"
                                 "frame shots/a.png\n"
                                 "dice $EXPORTED $DATA/ref.nii.gz label 3 >= 0.8\n",
                                 "s");
    ASSERT_EQ(s.steps.size(), 14U);
    using C = script::Condition;
    const auto wait = [&](int n) { return std::get<script::WaitStep>(s.steps[n].kind); };
    const auto expect = [&](int n) { return std::get<script::ExpectStep>(s.steps[n].kind); };
    EXPECT_EQ(wait(0).condition.kind, C::Converged);
    EXPECT_DOUBLE_EQ(wait(0).timeoutSeconds, 30.0);
    EXPECT_EQ(wait(1).condition.kind, C::Loaded);
    EXPECT_DOUBLE_EQ(wait(1).timeoutSeconds, script::kDefaultWaitTimeout);
    EXPECT_EQ(wait(2).condition.state, State::Paused);
    EXPECT_EQ(wait(3).condition.count, 200);
    EXPECT_DOUBLE_EQ(wait(4).condition.value, 1.5);
    EXPECT_EQ(expect(5).condition.state, State::Review);
    EXPECT_EQ(expect(6).condition.field, "volume_ml");
    EXPECT_EQ(expect(6).condition.op, C::Op::Greater);
    EXPECT_EQ(expect(7).condition.op, C::Op::GreaterEqual);
    EXPECT_EQ(expect(8).condition.kind, C::MessageHas);
    EXPECT_EQ(expect(8).condition.text, "converged after");
    EXPECT_EQ(expect(9).condition.kind, C::ExportedHas);
    EXPECT_EQ(expect(10).condition.kind, C::Converged);
    EXPECT_EQ(expect(11).condition.kind, C::Loaded);
    EXPECT_EQ(std::get<script::FrameStep>(s.steps[12].kind).path, "shots/a.png");
    const auto& dice = std::get<script::DiceStep>(s.steps[13].kind);
    EXPECT_EQ(dice.mask, "$EXPORTED");
    EXPECT_EQ(dice.label, 3);
    EXPECT_DOUBLE_EQ(dice.value, 0.8);
}

TEST(ScriptParse, TheBoxVerb) {
    const auto box = action<model::SetBox>("box 1 2 3 40 50 60");
    EXPECT_EQ(box.box.lo, glm::ivec3(1, 2, 3));
    EXPECT_EQ(box.box.hi, glm::ivec3(40, 50, 60));
    // Whether it fits the scan, or is inverted, is the workflow's to say (WorkflowBox).
    EXPECT_EQ(action<model::SetBox>("box 9 2 3 4 5 6").box.lo.x, 9);
    action<model::ClearBox>("box clear");
    const std::string errors = parseError("box 1 2 3 4 5\n"
                                          "box 1 2 3 4 5 6 7\n"
                                          "box 1.5 2 3 4 5 6\n"
                                          "box clear now\n");
    const std::vector<std::string> expected = {
        "s.session:1: missing the box's k1",
        "s.session:2: unexpected '7' (usage: box I0 J0 K0 I1 J1 K1 | box clear)",
        "s.session:3: the box's i0 must be a whole number, not '1.5'",
        "s.session:4: unexpected 'now' (usage: box I0 J0 K0 I1 J1 K1 | box clear)",
    };
    for (const std::string& line : expected) {
        EXPECT_NE(errors.find(line), std::string::npos) << line << "\nin:\n" << errors;
    }
}

TEST(ScriptParse, SpeedVerbsAndChecks) {
    EXPECT_EQ(action<model::SetSpeed>("speed threshold").kind, model::SpeedKind::Threshold);
    EXPECT_EQ(action<model::SetSpeed>("speed edge").kind, model::SpeedKind::Edge);
    EXPECT_EQ(action<model::SetSpeed>("speed classify").kind, model::SpeedKind::Classify);
    const auto outside = action<model::MarkOutside>("outside 10 20 30 4.5");
    EXPECT_EQ(outside.voxel, glm::dvec3(10, 20, 30));
    EXPECT_DOUBLE_EQ(outside.radiusMm, 4.5);
    EXPECT_DOUBLE_EQ(action<model::MarkOutside>("outside 1 2 3").radiusMm, 0.0)
        << "no radius: the probe's";
    action<model::ClearExamples>("clear_examples");
    EXPECT_TRUE(action<model::SetOutsideMode>("outside_mode on").outside);
    EXPECT_FALSE(action<model::SetOutsideMode>("outside_mode off").outside);

    const Script s = parseScript("wait speed classify timeout 5\n"
                                 "expect speed edge\n"
                                 "expect outside_examples == 1\n"
                                 "wait until inside_examples >= 2\n"
                                 "expect outside_mode == 1\n",
                                 "s");
    ASSERT_EQ(s.steps.size(), 5U);
    using C = script::Condition;
    const auto& wait = std::get<script::WaitStep>(s.steps[0].kind);
    EXPECT_EQ(wait.condition.kind, C::Speed);
    EXPECT_EQ(wait.condition.speed, model::SpeedKind::Classify);
    EXPECT_DOUBLE_EQ(wait.timeoutSeconds, 5.0);
    const auto& expect = std::get<script::ExpectStep>(s.steps[1].kind);
    EXPECT_EQ(expect.condition.kind, C::Speed);
    EXPECT_EQ(expect.condition.speed, model::SpeedKind::Edge);
    EXPECT_EQ(std::get<script::ExpectStep>(s.steps[2].kind).condition.field, "outside_examples");

    const std::string errors = parseError("speed gradient\n"
                                          "speed\n"
                                          "speed edge now\n"
                                          "outside 1 2\n"
                                          "outside 1 2 3 0\n"
                                          "clear_examples all\n"
                                          "outside_mode maybe\n"
                                          "expect speed fast\n"
                                          "wait speed\n");
    const std::vector<std::string> expected = {
        "s.session:1: speed 'gradient': give threshold, edge or classify",
        "s.session:2: ",
        "s.session:3: unexpected 'now' (usage: speed threshold|edge|classify)",
        "s.session:4: ",
        "s.session:5: the example's radius (mm) '0' is outside",
        "s.session:6: unexpected 'all' (usage: clear_examples)",
        "s.session:7: outside_mode 'maybe': give on or off",
        "s.session:8: speed 'fast': give threshold, edge or classify",
        "s.session:9: ",
    };
    for (const std::string& e : expected) {
        EXPECT_NE(errors.find(e), std::string::npos) << "missing: " << e << "\nin:\n" << errors;
    }
    EXPECT_EQ(std::count(errors.begin(), errors.end(), '\n') + 1,
              static_cast<long>(expected.size()))
        << errors;
}

TEST(ScriptPlayer, SpeedConditionsReadTheSpeedInForce) {
    workflow::Status st;
    st.speed = model::SpeedKind::Classify;
    st.speedInForce = model::SpeedKind::Edge;
    st.insideExamples.resize(2);
    script::Condition c;
    c.kind = script::Condition::Speed;
    c.speed = model::SpeedKind::Classify;
    EXPECT_FALSE(script::holds(c, st)) << "chosen, but waiting for examples";
    EXPECT_EQ(script::observed(c, st), "speed is edge (classify chosen)");
    st.speedInForce = model::SpeedKind::Classify;
    EXPECT_TRUE(script::holds(c, st));
    EXPECT_EQ(script::observed(c, st), "speed is classify");
    EXPECT_EQ(script::statusField(st, "inside_examples"), 2.0);
    EXPECT_EQ(script::statusField(st, "outside_examples"), 0.0);
}

TEST(ScriptParse, WaitUntilAField) {
    const Script s = parseScript("wait until seeds >= 2 timeout 20\n"
                                 "wait until volume_ml < 1.5\n",
                                 "s");
    ASSERT_EQ(s.steps.size(), 2U);
    using C = script::Condition;
    const auto& seeds = std::get<script::WaitStep>(s.steps[0].kind);
    EXPECT_EQ(seeds.condition.kind, C::Compare);
    EXPECT_EQ(seeds.condition.field, "seeds");
    EXPECT_EQ(seeds.condition.op, C::Op::GreaterEqual);
    EXPECT_DOUBLE_EQ(seeds.condition.value, 2.0);
    EXPECT_DOUBLE_EQ(seeds.timeoutSeconds, 20.0);
    const auto& volume = std::get<script::WaitStep>(s.steps[1].kind);
    EXPECT_EQ(volume.condition.op, C::Op::Less);
    EXPECT_DOUBLE_EQ(volume.timeoutSeconds, script::kDefaultWaitTimeout);

    EXPECT_NE(parseError("wait until colour == 3\n")
                  .find("s.session:1: wait until 'colour': not a "
                        "field (volume_ml, iterations"),
              std::string::npos)
        << parseError("wait until colour == 3\n");
    EXPECT_NE(parseError("wait until seeds ~ 3\n").find("s.session:1: '~' is not a comparison"),
              std::string::npos);
    EXPECT_NE(parseError("wait until seeds >= 2 soon\n").find("s.session:1: unexpected 'soon'"),
              std::string::npos)
        << parseError("wait until seeds >= 2 soon\n");
}

TEST(ScriptParse, TimingCommentsAndLines) {
    const Script s = parseScript("# a session\n"
                                 "\n"
                                 "   run   # go\r\n"
                                 "at 1.25 pause\n"
                                 "after 0.5 load \"x # not a comment.nii\"\n"
                                 "at 1.25 run\n",
                                 "s");
    ASSERT_EQ(s.steps.size(), 4U);
    EXPECT_EQ(s.steps[0].line, 3);
    EXPECT_EQ(s.steps[0].text, "run");
    EXPECT_EQ(s.steps[0].timing.kind, script::Timing::Next);
    EXPECT_EQ(s.steps[1].timing.kind, script::Timing::At);
    EXPECT_DOUBLE_EQ(s.steps[1].timing.seconds, 1.25);
    EXPECT_EQ(s.steps[2].timing.kind, script::Timing::After);
    EXPECT_EQ(std::get<model::LoadScan>(std::get<script::ActionStep>(s.steps[2].kind).action).path,
              "x # not a comment.nii");
    EXPECT_EQ(s.steps[3].line, 6);
}

TEST(ScriptParse, EveryBadLineIsNamedOnce) {
    const std::string errors = parseError("run\n"
                                          "jump 1 2\n"
                                          "at -1 run\n"
                                          "at 5 run\n"
                                          "at 4 run\n"
                                          "seed 1 2 nan\n"
                                          "seed 1 2 1e400\n"
                                          "set eps inf\n"
                                          "set gamma 3\n"
                                          "touch press 0 1 1\n"
                                          "key hyper\n"
                                          "wait forever\n"
                                          "expect volume_ml ~ 3\n"
                                          "load $HOME/x\n"
                                          "load \"open\n"
                                          "run now\n"
                                          "frame a.jpg\n"
                                          "at 9\n"
                                          "seed 1e9 0 0\n"
                                          "wait iterations 0\n");
    const std::vector<std::string> expected = {
        "s.session:2: unknown step 'jump'",
        "s.session:3: the time after 'at' '-1' is outside",
        "s.session:5: at 4 goes back in time (an earlier step is at 5)",
        "s.session:6: the voxel's k must be a finite number, not 'nan'",
        "s.session:7: the voxel's k '1e400' is out of range",
        "s.session:8: the value must be a finite number, not 'inf'",
        "s.session:9: unknown parameter 'gamma'",
        "s.session:10: touch 'press': give down, move or up",
        "s.session:11: unknown key 'hyper'",
        "s.session:12: wait 'forever': not a condition",
        "s.session:13: '~' is not a comparison",
        "s.session:14: unknown variable $HOME",
        "s.session:15: a quote is not closed",
        "s.session:16: unexpected 'now' (usage: run)",
        "s.session:17: frame 'a.jpg': the file name must end in .png",
        "s.session:18: 'at 9' names no step after the time",
        "s.session:19: the voxel's i '1e9' is outside",
        "s.session:20: the iterations '0' is outside [1, 100000000]",
    };
    for (const std::string& e : expected) {
        EXPECT_NE(errors.find(e), std::string::npos) << "missing: " << e << "\nin:\n" << errors;
    }
    // One line per bad line, nothing for the good ones.
    EXPECT_EQ(std::count(errors.begin(), errors.end(), '\n') + 1,
              static_cast<long>(expected.size()))
        << errors;
}

TEST(ScriptParse, StrokeReplaysADrag) {
    const auto add = action<model::PaintStroke>("stroke add 2.5 1 2 3 4 5 6 7 8 9");
    EXPECT_EQ(add.mode, model::StrokeMode::Add);
    EXPECT_DOUBLE_EQ(add.radius, 2.5);
    EXPECT_EQ(add.points, (std::vector<glm::dvec3>{{1, 2, 3}, {4, 5, 6}, {7, 8, 9}}));
    const auto erase = action<model::PaintStroke>("stroke erase brush 1 2 3");
    EXPECT_EQ(erase.mode, model::StrokeMode::Erase);
    EXPECT_DOUBLE_EQ(erase.radius, 0.0) << "the brush";
    EXPECT_EQ(erase.points.size(), 1U);
    EXPECT_EQ(action<model::PaintStroke>("stroke outside 3 0 0 0").mode,
              model::StrokeMode::Outside);
    const std::string errors = parseError("stroke paint 2 1 2 3\n"
                                          "stroke add 2 1 2\n"
                                          "stroke add brush\n"
                                          "stroke add 0 1 2 3\n"
                                          "stroke outside 2 1 2 nan\n");
    for (const std::string e :
         {"s.session:1: stroke 'paint': give add, erase or outside", "s.session:2: ",
          "s.session:3: ", "s.session:4: the radius (voxels) or brush '0' is outside",
          "s.session:5: the voxel's k must be a finite number, not 'nan'"}) {
        EXPECT_NE(errors.find(e), std::string::npos) << "missing: " << e << "\nin:\n" << errors;
    }
    EXPECT_EQ(std::count(errors.begin(), errors.end(), '\n') + 1, 5) << errors;
}

TEST(ScriptParse, WholeFileProblems) {
    EXPECT_EQ(parseError("# only a comment\n\n"), "s.session: the script has no steps");
    EXPECT_EQ(parseError(std::string("run\0pause", 9)),
              "s.session: not a text file (a NUL byte at offset 3)");
    EXPECT_NE(parseError("run\n\x01\x02\n").find("s.session:2: a control character (0x01)"),
              std::string::npos);
    // A binary file without a NUL byte is one line too, not one per line.
    std::string binary;
    for (int n = 0; n < 200; ++n) {
        binary += static_cast<char>(1 + n % 31);
    }
    EXPECT_EQ(
        parseError("run\n" + binary),
        "s.session: not a text file (control characters on 8 lines, the first 0x01 on line 2)");
    EXPECT_NE(parseError("run " + std::string(5000, 'x')).find("s.session:1: the line is 5004"),
              std::string::npos);
    EXPECT_NE(parseError(std::string(script::kMaxScriptBytes + 1, '#')).find("at most"),
              std::string::npos);
    // A flood of bad lines is cut, not echoed whole.
    std::string flood;
    for (int n = 0; n < 1000; ++n) {
        flood += "bad\n";
    }
    const std::string errors = parseError(flood);
    EXPECT_LE(std::count(errors.begin(), errors.end(), '\n'), 60);
    EXPECT_NE(errors.find("more errors after line 50 not listed"), std::string::npos);
}

TEST(ScriptParse, FilesThatAreNotScripts) {
    const auto dir = std::filesystem::temp_directory_path() / "steerseg_script_test";
    std::filesystem::create_directories(dir);
    try {
        script::loadScript(dir / "missing.session");
        FAIL();
    } catch (const ScriptError& e) {
        EXPECT_EQ(std::string(e.what()),
                  (dir / "missing.session").string() + ": no such script file");
    }
    EXPECT_THROW(script::loadScript(dir), ScriptError);
    const auto binary = dir / "binary.session";
    {
        std::ofstream out(binary, std::ios::binary);
        const unsigned char png[] = {0x89, 'P', 'N', 'G', 0x0D, 0x0A, 0x1A, 0x0A, 0, 0, 0, 13};
        out.write(reinterpret_cast<const char*>(png), sizeof png);
    }
    try {
        script::loadScript(binary);
        FAIL();
    } catch (const ScriptError& e) {
        EXPECT_NE(std::string(e.what()).find("not a text file"), std::string::npos) << e.what();
    }
    const auto good = dir / "good.session";
    std::ofstream(good) << "load builtin:sample\nwait loaded\n";
    EXPECT_EQ(script::loadScript(good).steps.size(), 2U);
    std::filesystem::remove_all(dir);
}

// --- the player ----------------------------------------------------------------------------

struct Recorder : script::ScriptSink {
    std::vector<std::string> log;
    double dice = 0.9;
    void action(const model::Action& a) override {
        if (const auto* load = std::get_if<model::LoadScan>(&a)) {
            log.push_back("load " + load->path);
        } else if (const auto* out = std::get_if<model::Export>(&a)) {
            log.push_back("export " + out->path);
        } else {
            log.push_back("action " + std::to_string(a.index()));
        }
    }
    void input(const platform::InputEvent& e) override {
        log.push_back("input " + std::to_string(static_cast<int>(e.kind)) +
                      " t=" + std::to_string(e.time));
    }
    void saveFrame(const std::filesystem::path& path) override {
        if (path.string().find("fail") != std::string::npos) {
            throw std::runtime_error("cannot write " + path.string());
        }
        log.push_back("frame " + path.string());
    }
    double maskDice(const std::filesystem::path& mask, const std::filesystem::path& reference,
                    int label) override {
        log.push_back("dice " + mask.string() + " " + reference.string() + " " +
                      std::to_string(label));
        return dice;
    }
    void answerResume(bool resume) override {
        log.push_back(resume ? "autosave resume" : "autosave discard");
    }
};

ScriptPlayer player(const std::string& text, script::Variables vars = {}) {
    return ScriptPlayer(parseScript(text, "t.session"), std::move(vars));
}

TEST(ScriptPlayer, AnswersTheResumeOffer) {
    ScriptPlayer p = player("autosave resume\nautosave discard\n");
    Recorder r;
    workflow::Status st;
    p.poll(0.0, st, r);
    p.poll(0.1, st, r);
    ASSERT_EQ(r.log.size(), 2U);
    EXPECT_EQ(r.log[0], "autosave resume");
    EXPECT_EQ(r.log[1], "autosave discard");
    EXPECT_TRUE(p.finished());
    EXPECT_THROW((void)script::parseScript("autosave maybe\n", "s"), script::ScriptError);
    EXPECT_THROW((void)script::parseScript("autosave\n", "s"), script::ScriptError);
}

TEST(ScriptPlayer, EmitsTimedStepsWhenDue) {
    ScriptPlayer p = player("at 1 run\n"
                            "after 0.5 pause\n"
                            "tap 5 5\n"
                            "at 3 toggle\n");
    Recorder r;
    workflow::Status st;
    p.poll(10.0, st, r); // the script's start
    EXPECT_TRUE(r.log.empty());
    p.poll(10.9, st, r);
    EXPECT_TRUE(r.log.empty());
    p.poll(11.0, st, r);
    ASSERT_EQ(r.log.size(), 1U);
    // A late frame: the pause (due 11.5) and the tap that follows at once both go out; the
    // schedule keeps its times, so the toggle is still due at 13.
    p.poll(11.7, st, r);
    ASSERT_EQ(r.log.size(), 4U);
    EXPECT_EQ(r.log[2], "input 0 t=11.700000");
    EXPECT_EQ(r.log[3], "input 2 t=11.700000");
    p.poll(12.99, st, r);
    EXPECT_EQ(r.log.size(), 4U);
    EXPECT_FALSE(p.finished());
    p.poll(13.0, st, r);
    EXPECT_EQ(r.log.size(), 5U);
    EXPECT_TRUE(p.finished());
    EXPECT_FALSE(p.failed());
}

TEST(ScriptPlayer, WaitsHoldUntilTheStatusSatisfiesThem) {
    ScriptPlayer p = player("load builtin:sample\n"
                            "wait loaded\n"
                            "run\n"
                            "wait iterations 50\n"
                            "wait converged\n"
                            "expect state paused\n"
                            "finish\n");
    Recorder r;
    workflow::Status st;
    p.poll(0.0, st, r);
    EXPECT_EQ(r.log, std::vector<std::string>{"load builtin:sample"});
    st.state = State::Loading;
    p.poll(0.1, st, r);
    p.poll(0.2, st, r);
    EXPECT_EQ(r.log.size(), 1U);
    st.state = State::Inspect;
    p.poll(0.3, st, r); // loaded -> run goes out; the wait for iterations waits for a frame
    ASSERT_EQ(r.log.size(), 2U);
    st.state = State::Evolving;
    st.iterations = 10;
    p.poll(0.4, st, r); // the wait starts counting at 10
    st.iterations = 59;
    p.poll(0.5, st, r);
    EXPECT_EQ(p.nextStep(), 3U);
    st.iterations = 60;
    st.converged = false;
    p.poll(0.6, st, r);
    EXPECT_EQ(p.nextStep(), 4U); // now waiting for convergence
    st.iterations = 400;
    p.poll(5.0, st, r);
    EXPECT_EQ(p.nextStep(), 4U);
    st.converged = true;
    st.state = State::Paused;
    p.poll(5.1, st, r);
    EXPECT_TRUE(p.finished()) << p.failure();
    EXPECT_EQ(r.log.size(), 3U);
}

// `wait until` holds later steps until the status shows the field's value, whatever set it
// (input from outside the script), and times out with the value it saw.
TEST(ScriptPlayer, WaitUntilAFieldHoldsUntilItHolds) {
    ScriptPlayer p = player("wait until seeds >= 2 timeout 5\nrun\n");
    Recorder r;
    workflow::Status st;
    st.seeds = 1;
    p.poll(0.0, st, r);
    p.poll(4.9, st, r);
    EXPECT_TRUE(r.log.empty());
    EXPECT_FALSE(p.failed());
    st.seeds = 2;
    p.poll(4.95, st, r);
    EXPECT_EQ(r.log.size(), 1U); // the run
    EXPECT_TRUE(p.finished()) << p.failure();

    ScriptPlayer late = player("wait until seeds >= 2 timeout 5\n");
    st.seeds = 1;
    late.poll(10.0, st, r);
    late.poll(15.0, st, r);
    ASSERT_TRUE(late.failed());
    EXPECT_EQ(late.failure(),
              "t.session:1: wait until seeds >= 2 timeout 5: timed out after 5 s (seeds is 1)");
}

TEST(ScriptPlayer, ChecksSeeTheStatusOfTheFrameAfterAnAction) {
    ScriptPlayer p = player("seed 1 2 3 4\nexpect seeds == 1\n");
    Recorder r;
    workflow::Status st;
    p.poll(0.0, st, r); // the seed goes out; the check is not judged on this stale status
    EXPECT_FALSE(p.failed());
    st.seeds = 1;
    p.poll(0.02, st, r);
    EXPECT_TRUE(p.finished()) << p.failure();
}

// A frame shows the screen as the steps before it left it: the next step waits for the
// following frame, or a `finish` after it would already show in the picture.
TEST(ScriptPlayer, AFrameEndsTheCallSoLaterStepsMissThePicture) {
    ScriptPlayer p = player("run\nframe a.png\nfinish\n");
    Recorder r;
    workflow::Status st;
    p.poll(0.0, st, r);
    ASSERT_EQ(r.log.size(), 2U);
    EXPECT_EQ(r.log.back(), "frame a.png");
    p.poll(0.02, st, r);
    EXPECT_EQ(r.log.size(), 3U);
    EXPECT_TRUE(p.finished());
}

TEST(ScriptPlayer, FailedChecksNameTheLine) {
    ScriptPlayer p = player("# comment\nexpect state review # the end\nrun\n");
    Recorder r;
    workflow::Status st;
    st.state = State::Paused;
    p.poll(0.0, st, r);
    ASSERT_TRUE(p.failed());
    EXPECT_EQ(p.failure(), "t.session:2: expect state review: state is paused");
    p.poll(1.0, st, r); // nothing after a failure
    EXPECT_TRUE(r.log.empty());

    ScriptPlayer q = player("expect volume_ml > 1.5\n");
    st.volumeMl = 1.25;
    q.poll(0.0, st, r);
    EXPECT_EQ(q.failure(), "t.session:1: expect volume_ml > 1.5: volume_ml is 1.25");

    ScriptPlayer m = player("expect message contains \"done\"\n");
    st.message = "loading";
    m.poll(0.0, st, r);
    EXPECT_EQ(m.failure(), "t.session:1: expect message contains \"done\": message is \"loading\"");
}

TEST(ScriptPlayer, WaitsTimeOut) {
    ScriptPlayer p = player("wait converged timeout 2\n");
    Recorder r;
    workflow::Status st;
    st.state = State::Evolving;
    st.iterations = 77;
    p.poll(100.0, st, r);
    p.poll(101.9, st, r);
    EXPECT_FALSE(p.failed());
    p.poll(102.0, st, r);
    ASSERT_TRUE(p.failed());
    EXPECT_EQ(p.failure(), "t.session:1: wait converged timeout 2: timed out after 2 s (not "
                           "converged, state is evolving, 77 iterations)");

    // The default timeout, so a script that waits for something that never comes ends.
    ScriptPlayer d = player("wait state review\n");
    d.poll(0.0, st, r);
    d.poll(script::kDefaultWaitTimeout - 0.1, st, r);
    EXPECT_FALSE(d.failed());
    d.poll(script::kDefaultWaitTimeout, st, r);
    EXPECT_TRUE(d.failed());
}

TEST(ScriptPlayer, WaitsFailEarlyOnErrorsAndAStoppedSolver) {
    Recorder r;
    workflow::Status st;
    ScriptPlayer load = player("load /nope.nii\nwait loaded\n");
    load.poll(0.0, st, r);
    st.state = State::Loading;
    load.poll(0.1, st, r);
    st.state = State::NoScan;
    st.message = "/nope.nii: no such file";
    load.poll(0.2, st, r);
    EXPECT_EQ(load.failure(),
              "t.session:2: wait loaded: the scan did not load: /nope.nii: no such file");

    st = {};
    st.state = State::Error;
    st.message = "GPU lost";
    ScriptPlayer error = player("wait converged\n");
    error.poll(0.0, st, r);
    EXPECT_EQ(error.failure(), "t.session:1: wait converged: the workflow is in error: GPU lost");
    ScriptPlayer waitsForError = player("wait state error\n");
    waitsForError.poll(0.0, st, r);
    EXPECT_TRUE(waitsForError.finished());

    st = {};
    st.state = State::Seeding; // a status from before the run: not a stop
    ScriptPlayer iterations = player("wait iterations 100\n");
    iterations.poll(0.0, st, r);
    st.state = State::Evolving;
    st.iterations = 30;
    iterations.poll(0.1, st, r);
    st.state = State::Paused;
    st.converged = true;
    iterations.poll(0.2, st, r);
    EXPECT_EQ(iterations.failure(), "t.session:1: wait iterations 100: the solver stopped (30 "
                                    "iterations, state is paused) after 30 of 100 iterations");
}

TEST(ScriptPlayer, VariablesAndPaths) {
    const std::string text = "load $SCAN\n"
                             "export mask.nii.gz\n"
                             "frame shots/one.png\n"
                             "frame /abs/two.png\n"
                             "dice $EXPORTED ${DATA}/ref.nii.gz >= 0.8\n";
    try {
        player(text, {});
        FAIL();
    } catch (const ScriptError& e) {
        EXPECT_EQ(std::string(e.what()),
                  "t.session:1: $SCAN is not set (give --scan PATH)\n"
                  "t.session:5: $DATA is not set (set STEERSEG_DATA_DIR to the folder of real "
                  "scans)");
    }
    ScriptPlayer p = player(text, {{"SCAN", "/scans/ct.nii"}, {"DATA", "/data"}, {"OUT", "/out"}});
    Recorder r;
    workflow::Status st;
    p.poll(0.0, st, r);
    st.exportedPath = "/out/mask.nii.gz";
    for (double t = 0.1; t < 0.5 && !p.finished(); t += 0.1) { // each frame ends a call
        p.poll(t, st, r);
    }
    EXPECT_TRUE(p.finished()) << p.failure();
    EXPECT_EQ(r.log, (std::vector<std::string>{"load /scans/ct.nii", "export /out/mask.nii.gz",
                                               "frame /out/shots/one.png", "frame /abs/two.png",
                                               "dice /out/mask.nii.gz /data/ref.nii.gz -1"}));
}

// The kiosk's DICOM node: a script waits for a received series, loads the newest complete one
// ($RECEIVED, as a tap on its button would) and waits for the outbox to empty.
TEST(ScriptPlayer, ReceivedSeriesAndTheOutbox) {
    ScriptPlayer p = player("wait until received >= 1 timeout 5\n"
                            "load $RECEIVED\n"
                            "wait until outbox == 0 timeout 5\n");
    Recorder r;
    workflow::Status st;
    st.received = {{"/store/1.2/1.2.9", "CT (3 images) - arriving", true}};
    st.outbox = {"seg.dcm to pacs: queued"};
    p.poll(0.0, st, r);
    EXPECT_TRUE(r.log.empty()) << "an arriving series is not received yet";
    st.received.push_back({"/store/1.2/1.2.3", "CT (60 images)", false});
    p.poll(0.1, st, r);
    p.poll(0.2, st, r);
    EXPECT_EQ(r.log, (std::vector<std::string>{"load /store/1.2/1.2.3"}));
    EXPECT_FALSE(p.finished());
    st.outbox.clear();
    p.poll(0.3, st, r);
    EXPECT_TRUE(p.finished()) << p.failure();
}

// The PACS verbs (docs/scripts.md): the form's keys by the config's names, a retrieve of the
// last search's first study ($FOUND, known when the step runs), and their bad lines.
TEST(ScriptParse, PacsVerbs) {
    const auto s =
        action<model::SearchPacs>("search patient_id PID-7 study_date last_7_days peer pacs");
    EXPECT_EQ(s.peer, "pacs");
    EXPECT_EQ(s.keys.patientId, "PID-7");
    EXPECT_EQ(s.keys.studyDate, "last_7_days");
    EXPECT_EQ(action<model::SearchPacs>("search patient_name \"DOE*\"").keys.patientName, "DOE*");
    const auto r = action<model::RetrievePacs>("retrieve 1.2.3 1.2.3.4 peer archive");
    EXPECT_EQ(r.studyUid, "1.2.3");
    EXPECT_EQ(r.seriesUid, "1.2.3.4");
    EXPECT_EQ(r.peer, "archive");
    EXPECT_EQ(action<model::RetrievePacs>("retrieve $FOUND").studyUid, "$FOUND");
    action<model::CancelRetrieve>("cancel_retrieve");
    EXPECT_NE(parseError("search birth_date 1970\n").find("search 'birth_date'"),
              std::string::npos);
    EXPECT_NE(parseError("search study_date yesterday-ish\n").find("study_date"),
              std::string::npos);
    EXPECT_NE(parseError("retrieve 1.2.x\n").find("not a DICOM UID"), std::string::npos);
    EXPECT_NE(parseError("retrieve $FOUNDS\n").find("unknown variable $FOUNDS"), std::string::npos);
    // A study's series, and one series retrieved by the listing's first ($SERIES).
    const auto l = action<model::ListPacsSeries>("series 1.2.3 peer archive");
    EXPECT_EQ(l.studyUid, "1.2.3");
    EXPECT_EQ(l.peer, "archive");
    EXPECT_EQ(action<model::ListPacsSeries>("series $FOUND").studyUid, "$FOUND");
    EXPECT_EQ(action<model::ListPacsSeries>("series $FOUND").peer, "");
    const auto one = action<model::RetrievePacs>("retrieve $FOUND $SERIES peer archive");
    EXPECT_EQ(one.seriesUid, "$SERIES");
    EXPECT_EQ(one.peer, "archive");
    EXPECT_EQ(action<model::RetrievePacs>("retrieve 1.2.3 peer archive").seriesUid, "");
    // The refusals: each line's error names what is wrong.
    const std::vector<std::pair<std::string, std::string>> refused{
        {"series\n", "missing the study's UID"},
        {"series 1.2.x\n", "not a DICOM UID"},
        {"series $SERIESS\n", "unknown variable $SERIESS"},
        {"series 1.2.3 peer\n", "missing the peer's name"},
        {"series 1.2.3 peer \"\"\n", "the peer's name is empty"},
        {"series 1.2.3 archive\n", "unexpected"},
        {"series 1.2.3 peer a b\n", "unexpected"},
        {"retrieve 1.2.3 peer\n", "missing the peer's name"},
        {"retrieve 1.2.3 1.2.x\n", "not a DICOM UID"},
        {"retrieve 1.2.3 1.2.4 archive\n", "unexpected"},
        {"search peer\n", "missing the peer's name"},
        {"cancel_retrieve now\n", "unexpected"},
    };
    for (const auto& [line, why] : refused) {
        const std::string error = parseError(line);
        EXPECT_EQ(error.rfind("s.session:1: ", 0), 0U) << line << error;
        EXPECT_NE(error.find(why), std::string::npos) << line << error;
    }
}

// `series $FOUND` lists the last search's first study, `retrieve $FOUND $SERIES` fetches the
// listing's first series; the waits read the listing's counters. A peer the kiosk's status does
// not offer fails the step at once, naming the peers it has.
TEST(ScriptPlayer, SeriesOfTheFoundStudyAndTheFirstSeriesRetrieved) {
    struct Sink : Recorder {
        std::vector<model::Action> pacs;
        void action(const model::Action& a) override {
            if (std::holds_alternative<model::ListPacsSeries>(a) ||
                std::holds_alternative<model::RetrievePacs>(a)) {
                pacs.push_back(a);
            }
        }
    } r;
    ScriptPlayer p = player("series $FOUND peer archive\n"
                            "wait until series_listings >= 1 timeout 5\n"
                            "expect series_found == 2\nexpect listing_series == 0\n"
                            "retrieve $FOUND $SERIES peer archive\n");
    workflow::Status st;
    st.pacs.peers = {"pacs", "archive"};
    st.pacs.studies = {{"1.2.840.5", "2024-01-05  DOE JANE"}};
    p.poll(0.0, st, r);
    ASSERT_EQ(r.pacs.size(), 1U);
    EXPECT_EQ(std::get<model::ListPacsSeries>(r.pacs[0]).studyUid, "1.2.840.5");
    EXPECT_EQ(std::get<model::ListPacsSeries>(r.pacs[0]).peer, "archive");
    st.pacs.listingSeries = true;
    p.poll(0.1, st, r);
    EXPECT_EQ(r.pacs.size(), 1U) << "the listing has not ended";
    st.pacs.listingSeries = false;
    st.pacs.seriesListings = 1;
    st.pacs.series = {{"1.2.840.5.2", "CT", "2", "", 60}, {"1.2.840.5.1", "SEG", "", "", 1}};
    p.poll(0.2, st, r);
    p.poll(0.3, st, r);
    ASSERT_EQ(r.pacs.size(), 2U) << p.failure();
    const auto& get = std::get<model::RetrievePacs>(r.pacs[1]);
    EXPECT_EQ(get.studyUid, "1.2.840.5");
    EXPECT_EQ(get.seriesUid, "1.2.840.5.2");
    EXPECT_TRUE(p.finished()) << p.failure();

    Recorder plain;
    ScriptPlayer unknown = player("search peer archiv patient_id P\n");
    unknown.poll(0.0, st, plain);
    EXPECT_EQ(unknown.failure(), "t.session:1: search peer archiv patient_id P: no query peer "
                                 "named 'archiv' (the config's: pacs, archive)");
    ScriptPlayer none = player("series 1.2.3 peer pacs\n");
    none.poll(0.0, workflow::Status{}, plain);
    EXPECT_NE(none.failure().find("no query peer named 'pacs' (none in the config)"),
              std::string::npos)
        << none.failure();
}

TEST(ScriptPlayer, RetrieveTakesTheFirstStudyTheLastSearchFound) {
    struct Sink : Recorder {
        std::vector<model::RetrievePacs> retrieves;
        void action(const model::Action& a) override {
            if (const auto* r = std::get_if<model::RetrievePacs>(&a)) {
                retrieves.push_back(*r);
            }
        }
    } r;
    ScriptPlayer p = player("search patient_id P\nwait until found >= 1 timeout 5\n"
                            "retrieve $FOUND\nwait until retrieved == 3 timeout 5\n"
                            "expect retrieve_expected == 3\n");
    workflow::Status st;
    p.poll(0.0, st, r);
    p.poll(0.1, st, r);
    EXPECT_TRUE(r.retrieves.empty()) << "nothing found yet";
    st.pacs.studies = {{"1.2.840.5", "2024-01-05  DOE JANE"}, {"1.2.840.6", "other"}};
    p.poll(0.2, st, r);
    p.poll(0.3, st, r);
    ASSERT_EQ(r.retrieves.size(), 1U);
    EXPECT_EQ(r.retrieves[0].studyUid, "1.2.840.5");
    st.pacs.received = 3;
    st.pacs.expected = 3;
    p.poll(0.4, st, r);
    p.poll(0.5, st, r);
    EXPECT_TRUE(p.finished()) << p.failure();
}

TEST(ScriptPlayer, DiceAndSinkFailures) {
    Recorder r;
    workflow::Status st;
    r.dice = 0.42;
    ScriptPlayer low = player("dice m.nii.gz r.nii.gz label 2 >= 0.8\n");
    low.poll(0.0, st, r);
    EXPECT_EQ(low.failure(), "t.session:1: dice m.nii.gz r.nii.gz label 2 >= 0.8: Dice is 0.4200");
    ScriptPlayer nothing = player("dice $EXPORTED r.nii.gz >= 0.8\n");
    nothing.poll(0.0, st, r);
    EXPECT_EQ(nothing.failure(),
              "t.session:1: dice $EXPORTED r.nii.gz >= 0.8: no mask to compare (nothing was "
              "exported yet)");
    ScriptPlayer frame = player("frame fail.png\n");
    frame.poll(0.0, st, r);
    EXPECT_EQ(frame.failure(), "t.session:1: frame fail.png: cannot write fail.png");
}

TEST(ScriptPlayer, ClockGoingBackFails) {
    ScriptPlayer p = player("at 5 run\n");
    Recorder r;
    workflow::Status st;
    p.poll(2.0, st, r);
    p.poll(1.0, st, r);
    EXPECT_TRUE(p.failed());
    EXPECT_NE(p.failure().find("the script clock went back"), std::string::npos);
}

TEST(ScriptParse, RawDeviceRecords) {
    const Script s = parseScript("raw shuttle hid 0003000000\n"
                                 "after 0.5 raw pedal gpio 1\n"
                                 "raw 10.000 powermate evdev 2 7 -1\n"
                                 "raw 10.250 powermate evdev 0 0 0\n"
                                 "raw 10.300 pedal gpio 0\n"
                                 "replay knob_turn.rec\n"
                                 "replay $DATA/knobs/turn.rec\n",
                                 "scenarios/knobs.session");
    ASSERT_EQ(s.steps.size(), 7U);
    const auto& first = std::get<script::RawStep>(s.steps[0].kind);
    ASSERT_TRUE(first.record);
    EXPECT_EQ(first.record->device, "shuttle");
    EXPECT_EQ(first.record->kind, platform::input::RawRecord::Kind::HidReport);
    EXPECT_EQ(first.record->bytes, (std::vector<std::uint8_t>{0, 3, 0, 0, 0}));
    EXPECT_EQ(s.steps[0].timing.kind, script::Timing::Next);
    EXPECT_TRUE(std::get<script::RawStep>(s.steps[1].kind).record->active);
    EXPECT_EQ(s.steps[1].timing.kind, script::Timing::After);
    // Lines pasted from a recording keep their spacing: the first of the run at once, the
    // others as far after the one before as recorded.
    EXPECT_EQ(s.steps[2].timing.kind, script::Timing::Next);
    EXPECT_EQ(s.steps[3].timing.kind, script::Timing::After);
    EXPECT_DOUBLE_EQ(s.steps[3].timing.seconds, 0.25);
    EXPECT_NEAR(s.steps[4].timing.seconds, 0.05, 1e-9);
    EXPECT_EQ(std::get<script::RawStep>(s.steps[2].kind).record->value, -1);
    // A replay's relative path is the script's folder's.
    EXPECT_EQ(std::get<script::RawStep>(s.steps[5].kind).recording, "scenarios/knob_turn.rec");
    EXPECT_EQ(std::get<script::RawStep>(s.steps[6].kind).recording, "$DATA/knobs/turn.rec");

    for (const char* bad : {"raw", "raw shuttle hid 0g", "raw Shuttle hid 00", "raw pedal gpio 2",
                            "raw 1.0 pedal", "replay"}) {
        const std::string error = parseError(std::string(bad) + "\n");
        EXPECT_EQ(error.rfind("s.session:1: ", 0), 0U) << bad << ": " << error;
        EXPECT_EQ(error.find('\n'), std::string::npos) << error;
    }
    EXPECT_NE(parseError("raw\n").find("write 'raw DEVICE KIND DATA'"), std::string::npos);
}

struct RawRecorder : Recorder {
    std::vector<platform::input::RawRecord> raws;
    std::vector<std::string> replays;
    void raw(const platform::input::RawRecord& r) override { raws.push_back(r); }
    void replay(const std::filesystem::path& p) override { replays.push_back(p.string()); }
};

// Records carry the time their step was due, not the (late) frame's: two knob detents 0.2 s
// apart in the script stay 0.2 s apart for the decoders after a frame that took a second.
TEST(ScriptPlayer, RawRecordsCarryTheTimeTheyWereDue) {
    ScriptPlayer p = player("raw pedal gpio 1\nafter 2 raw pedal gpio 0\nreplay $DATA/t.rec\n",
                            {{"DATA", "/data"}});
    RawRecorder r;
    workflow::Status st;
    p.poll(10.0, st, r);
    p.poll(12.5, st, r);
    ASSERT_EQ(r.raws.size(), 2U);
    EXPECT_EQ(r.raws[0].time, 10.0);
    EXPECT_TRUE(r.raws[0].active);
    EXPECT_EQ(r.raws[1].time, 12.0);
    EXPECT_EQ(r.replays, (std::vector<std::string>{"/data/t.rec"}));
    EXPECT_TRUE(p.finished());

    // A sink that takes no raw input fails the step with one line.
    ScriptPlayer refused = player("raw pedal gpio 1\n");
    Recorder plain;
    refused.poll(0.0, st, plain);
    EXPECT_EQ(refused.failure(),
              "t.session:1: raw pedal gpio 1: raw device input is not taken here");
}

// --- the scenarios ------------------------------------------------------------------------

// Every session under tests/scenarios parses, and the real scans and labels it names exist.
TEST(ScriptScenarios, ParseAndNameExistingData) {
    const std::filesystem::path dir = STEERSEG_SCENARIO_DIR;
    const auto data = dataDir();
    int count = 0;
    for (const auto& entry : std::filesystem::directory_iterator(dir)) {
        if (entry.path().extension() != ".session") {
            continue;
        }
        ++count;
        SCOPED_TRACE(entry.path().string());
        const Script script = script::loadScript(entry.path());
        const ScriptPlayer p(
            script,
            {{"SCAN", "/scan.nii"}, {"DATA", data ? data->string() : "/data"}, {"OUT", "/out"}});
        if (!data) {
            continue;
        }
        for (const script::Step& step : p.script().steps) {
            std::vector<std::string> paths;
            if (const auto* a = std::get_if<script::ActionStep>(&step.kind)) {
                if (const auto* load = std::get_if<model::LoadScan>(&a->action)) {
                    paths.push_back(load->path);
                }
            } else if (const auto* dice = std::get_if<script::DiceStep>(&step.kind)) {
                paths.push_back(dice->reference);
            }
            for (const std::string& path : paths) {
                if (path.starts_with(data->string())) {
                    EXPECT_TRUE(std::filesystem::exists(path))
                        << "line " << step.line << ": " << path;
                }
            }
        }
    }
    EXPECT_GE(count, 2);
}

// --- the Dice check ------------------------------------------------------------------------

TEST(MaskDice, CountsOverlapAndRefusesOtherGrids) {
    const auto dir = std::filesystem::temp_directory_path() / "steerseg_dice_test";
    std::filesystem::create_directories(dir);
    Geometry g;
    g.dims = {4, 1, 1};
    const auto write = [&](const std::string& name, std::vector<std::uint8_t> v) {
        exports::writeMask(dir / name, g, v);
        return dir / name;
    };
    const auto a = write("a.nii.gz", {1, 1, 0, 0});
    const auto b = write("b.nii.gz", {1, 0, 1, 0});
    const auto empty = write("e.nii.gz", {0, 0, 0, 0});
    EXPECT_DOUBLE_EQ(script::maskDice(a, b, -1), 0.5);
    EXPECT_DOUBLE_EQ(script::maskDice(a, a, -1), 1.0);
    EXPECT_DOUBLE_EQ(script::maskDice(a, b, 1), 0.5);
    EXPECT_DOUBLE_EQ(script::maskDice(a, b, 2), 0.0); // no voxel has label 2
    EXPECT_DOUBLE_EQ(script::maskDice(empty, b, -1), 0.0);
    g.dims = {2, 2, 1};
    const auto other = write("o.nii.gz", {1, 1, 1, 1});
    EXPECT_THROW(script::maskDice(a, other, -1), std::runtime_error);
    EXPECT_THROW(script::maskDice(dir / "none.nii.gz", b, -1), std::exception);
    std::filesystem::remove_all(dir);
}

} // namespace
} // namespace steerseg::test
