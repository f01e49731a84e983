#include "support/workflow_rig.hpp"
#include "workflow/param_ranges.hpp"

#include <cmath>
#include <gtest/gtest.h>
#include <limits>

namespace steerseg::test {
namespace {

using namespace workflow;

using namespace model;

TEST(WorkflowParams, NiceStepsAreOneTwoFive) {
    EXPECT_DOUBLE_EQ(niceStep(1.0), 1.0);
    EXPECT_DOUBLE_EQ(niceStep(4.095), 5.0);
    EXPECT_DOUBLE_EQ(niceStep(0.0031), 0.002);
    EXPECT_DOUBLE_EQ(niceStep(0.0036), 0.005);
    EXPECT_DOUBLE_EQ(niceStep(65.535), 50.0);
    EXPECT_DOUBLE_EQ(niceStep(80.0), 100.0);
    EXPECT_DOUBLE_EQ(niceStep(0.0), 1.0);
    EXPECT_DOUBLE_EQ(niceStep(std::nan("")), 1.0);
}

TEST(WorkflowParams, RangesFollowTheScan) {
    ScanInfo s;
    s.dims = {512, 512, 1}; // a single image still gets an in-plane brush
    s.minValue = -1024.0;
    s.maxValue = 3071.0;
    const ParamRanges r = rangesFor(s);
    EXPECT_EQ(r[0].min, -1024.0);
    EXPECT_EQ(r[0].max, 3071.0);
    EXPECT_EQ(r[0].fineStep, 5.0);
    EXPECT_EQ(r[1].min, 0.0);
    EXPECT_EQ(r[1].max, 4095.0);
    EXPECT_EQ(r[2].max, 1.0);
    EXPECT_EQ(r[3].min, 1.0);
    EXPECT_EQ(r[3].max, 256.0);
    // Rounding to float must not step outside.
    const ParamRange odd{0.1, 0.30000000000000004, 0.001};
    EXPECT_LE(static_cast<double>(clampToFloat(odd, 1.0)), odd.max);
    EXPECT_GE(static_cast<double>(clampToFloat(odd, -1.0)), odd.min);
}

TEST(WorkflowParams, ProbeSetsTargetAndEpsWithTheFloor) {
    Rig rig; // eps floor 25, factor 2
    rig.load();
    rig.engine.probeStddev = 100.0;
    ASSERT_TRUE(rig.act(Probe{{15.0, 6.0, 4.0}, 3.0}).accepted);
    EXPECT_FLOAT_EQ(rig.status().params.T, 1000.0F); // the fake's mean at the far i edge
    EXPECT_FLOAT_EQ(rig.status().params.eps, 200.0F);
    EXPECT_EQ(rig.engine.params().eps, 200.0F);
    rig.engine.probeStddev = 1.0; // homogeneous tissue: the floor keeps the front moving
    ASSERT_TRUE(rig.act(Probe{{0.0, 6.0, 4.0}, 0.0}).accepted); // 0: the configured radius
    EXPECT_FLOAT_EQ(rig.status().params.T, -1000.0F);
    EXPECT_FLOAT_EQ(rig.status().params.eps, 25.0F);
    const Workflow::Outcome out = rig.act(Probe{{-40.0, 6.0, 4.0}, 2.0});
    EXPECT_FALSE(out.accepted);
    EXPECT_EQ(out.reason, "probe outside the scan");
    EXPECT_FALSE(rig.act(Probe{{1.0, 1.0, std::nan("")}, 2.0}).accepted);
    EXPECT_FLOAT_EQ(rig.status().params.eps, 25.0F); // a refusal changes nothing
    ASSERT_TRUE(rig.act(Undo{}).accepted);
    EXPECT_FLOAT_EQ(rig.status().params.eps, 200.0F);
    EXPECT_EQ(rig.engine.misuse(), 0) << rig.engine.lastMisuse();
}

TEST(WorkflowParams, PresetsSetSpeedWindowAndTransfer) {
    Rig rig;
    rig.load();
    ASSERT_EQ(rig.status().presets, (std::vector<std::string>{"CT soft tissue", "CT bone"}));
    ASSERT_TRUE(rig.act(ApplyPreset{"CT soft tissue"}).accepted);
    EXPECT_EQ(rig.status().params.T, 40.0F);
    EXPECT_EQ(rig.status().params.eps, 80.0F);
    EXPECT_FLOAT_EQ(rig.status().params.alpha, 0.7F);
    EXPECT_EQ(rig.status().preset, "CT soft tissue");
    EXPECT_EQ(rig.status().view.windowWidth, 400.0);
    EXPECT_EQ(rig.status().view.transfer, "ct_soft");
    EXPECT_EQ(rig.engine.params().T, 40.0F);
    // Changing the speed by hand means the preset no longer holds; the brush does not.
    ASSERT_TRUE(rig.act(SetParam{Param::Radius, 2.0}).accepted);
    EXPECT_EQ(rig.status().preset, "CT soft tissue");
    ASSERT_TRUE(rig.act(NudgeParam{Param::T, 1.0}).accepted);
    EXPECT_EQ(rig.status().preset, "");
    ASSERT_TRUE(rig.act(Undo{}).accepted);
    EXPECT_EQ(rig.status().preset, "CT soft tissue");
    const Workflow::Outcome out = rig.act(ApplyPreset{"MR tumour"});
    EXPECT_FALSE(out.accepted);
    EXPECT_EQ(out.reason, "unknown preset 'MR tumour'");
    // A preset beyond the scan's range is clamped into it.
    ASSERT_TRUE(rig.act(SetParam{Param::T, 1e9}).accepted);
    EXPECT_EQ(rig.status().params.T, 1000.0F);
}

TEST(WorkflowParams, ValuesAreClampedAndNonFiniteOnesRefused) {
    Rig rig;
    rig.load();
    ASSERT_TRUE(rig.act(SetParam{Param::Alpha, 7.0}).accepted);
    EXPECT_EQ(rig.status().params.alpha, 1.0F);
    ASSERT_TRUE(rig.act(SetParam{Param::Eps, -3.0}).accepted);
    EXPECT_EQ(rig.status().params.eps, 0.0F);
    ASSERT_TRUE(rig.act(NudgeParam{Param::Radius, 1e308}).accepted);
    EXPECT_EQ(rig.status().radius, 4.0);
    ASSERT_TRUE(rig.act(NudgeParam{Param::T, -1e308}).accepted);
    EXPECT_EQ(rig.status().params.T, -1000.0F);
    const double inf = std::numeric_limits<double>::infinity();
    EXPECT_FALSE(rig.act(SetParam{Param::T, inf}).accepted);
    EXPECT_FALSE(rig.act(NudgeParam{Param::T, std::nan("")}).accepted);
    EXPECT_FALSE(rig.act(NudgeSelected{-inf}).accepted);
    EXPECT_FALSE(rig.act(SelectParam{static_cast<Param>(-1)}).accepted);
    EXPECT_FALSE(rig.act(SetWindow{std::nan(""), 10.0}).accepted);
    EXPECT_FALSE(rig.act(ZoomView{inf}).accepted);
    EXPECT_EQ(rig.engine.misuse(), 0) << rig.engine.lastMisuse();
}

TEST(WorkflowParams, KnobDrivesTheSelectedParameter) {
    Rig rig;
    rig.load();
    ASSERT_TRUE(rig.act(SelectParam{Param::Alpha}).accepted);
    ASSERT_TRUE(rig.act(NudgeSelected{-10.0}).accepted);
    EXPECT_FLOAT_EQ(rig.status().params.alpha, 0.7F);
    ASSERT_TRUE(rig.act(CycleParam{1}).accepted);
    EXPECT_EQ(rig.status().selected, Param::Radius);
    ASSERT_TRUE(rig.act(NudgeSelected{-2.0}).accepted);
    EXPECT_EQ(rig.status().radius, 2.0);
    // A seed with no radius uses the brush.
    rig.seed({8.0, 6.0, 4.0}, 0.0);
    EXPECT_TRUE(rig.engine.inside({10, 6, 4}));
    EXPECT_FALSE(rig.engine.inside({11, 6, 4}));
}

TEST(WorkflowParams, ParametersAreLiveWhileEvolving) {
    Rig rig;
    rig.driveTo(State::Evolving);
    const int calls = rig.engine.setParamsCalls;
    ASSERT_TRUE(rig.act(SetParam{Param::Eps, 321.0}).accepted);
    EXPECT_EQ(rig.engine.setParamsCalls, calls + 1);
    EXPECT_EQ(rig.engine.params().eps, 321.0F);
    EXPECT_EQ(rig.state(), State::Evolving);
    ASSERT_TRUE(rig.act(SetParam{Param::Radius, 2.0}).accepted); // the brush is not the solver's
    EXPECT_EQ(rig.engine.setParamsCalls, calls + 1);
}

TEST(WorkflowParams, BadSettingsAreNamedInOneLine) {
    FakeEngine engine;
    Settings s = testSettings();
    s.maxUndo = 0;
    EXPECT_THROW(Workflow(engine, s), std::invalid_argument);
    s = testSettings();
    s.presets.push_back(s.presets.front());
    try {
        Workflow w(engine, s);
        FAIL() << "a duplicate preset was accepted";
    } catch (const std::invalid_argument& e) {
        EXPECT_NE(std::string(e.what()).find("named twice"), std::string::npos) << e.what();
    }
    s = testSettings();
    s.epsFloor = std::nan("");
    EXPECT_THROW(validateSettings(s), std::invalid_argument);
    s = testSettings();
    s.classifyPlaceReach = -1.0;
    EXPECT_THROW(validateSettings(s), std::invalid_argument);
}

} // namespace
} // namespace steerseg::test
