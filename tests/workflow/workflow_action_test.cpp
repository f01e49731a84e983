#include "model/action.hpp"

#include <cmath>
#include <gtest/gtest.h>
#include <set>
#include <string>
#include <utility>
#include <variant>

namespace steerseg::test {
namespace {

using namespace model;

TEST(WorkflowAction, ParamNamesRoundTrip) {
    for (int i = 0; i < kParamCount; ++i) {
        const auto p = static_cast<Param>(i);
        EXPECT_EQ(paramFromName(paramName(p)), p) << paramName(p);
    }
    EXPECT_EQ(paramName(Param::T), "T");
    EXPECT_EQ(paramName(Param::Eps), "eps");
    EXPECT_FALSE(paramFromName("Eps").has_value());
    EXPECT_FALSE(paramFromName("").has_value());
}

TEST(WorkflowAction, StateAndActionNamesAreDistinctSnakeCase) {
    std::set<std::string> states;
    for (int i = 0; i <= static_cast<int>(State::Error); ++i) {
        states.insert(std::string(stateName(static_cast<State>(i))));
    }
    EXPECT_EQ(states.size(), 10U);
    EXPECT_EQ(stateName(State::NoScan), "no_scan");

    // Every alternative of the variant, by index: each named, no two alike.
    std::set<std::string> actions;
    const auto nameAt = [](std::size_t i) {
        Action a;
        [&]<std::size_t... I>(std::index_sequence<I...>) {
            ((I == i ? (a = std::variant_alternative_t<I, Action>{}, 0) : 0), ...);
        }
        (std::make_index_sequence<std::variant_size_v<Action>>{});
        return std::string(actionName(a));
    };
    for (std::size_t i = 0; i < std::variant_size_v<Action>; ++i) {
        const std::string n = nameAt(i);
        EXPECT_EQ(n.find_first_not_of("abcdefghijklmnopqrstuvwxyz_"), std::string::npos) << n;
        actions.insert(n);
    }
    EXPECT_EQ(actions.size(), std::variant_size_v<Action>);
    EXPECT_EQ(actionName(LoadScan{}), "load_scan");
    EXPECT_EQ(actionName(NudgeSelected{}), "nudge_selected");
}

TEST(WorkflowAction, EveryBindableNameGivesItsAction) {
    const auto& names = bindableNames();
    EXPECT_EQ(std::set<std::string_view>(names.begin(), names.end()).size(), names.size());
    for (const std::string_view n : names) {
        const auto a = bindingAction(n, 1.0);
        ASSERT_TRUE(a.has_value()) << n;
        // The binding's name starts with its action's (or names it through a prefix).
        const std::string_view act = actionName(*a);
        const std::string_view stem = n.substr(0, n.find(':'));
        const bool matches =
            act == stem || act.starts_with(stem) || (stem == "select" && act == "select_param") ||
            (stem == "nudge" && act == "nudge_param") || (stem == "page" && act == "page_slice") ||
            (stem == "erase_mode" && act == "set_erase_mode") ||
            (stem == "outside_mode" && act == "set_outside_mode") ||
            (stem == "speed" && act == "set_speed") ||
            (stem.starts_with("rotate") && act == "rotate_view") ||
            (stem == "zoom" && act == "zoom_view");
        EXPECT_TRUE(matches) << n << " -> " << act;
    }
    for (const char* n : {"run", "undo", "nudge:T", "nudge_selected", "page:axial", "rotate_yaw",
                          "toggle_run", "proceed", "back", "quit"}) {
        EXPECT_TRUE(bindingAction(n, 1.0).has_value()) << n;
    }
}

TEST(WorkflowAction, BindingStepsCarryDirectionAndSize) {
    const auto nudge = std::get<NudgeParam>(*bindingAction("nudge:eps", -3.0));
    EXPECT_EQ(nudge.param, Param::Eps);
    EXPECT_EQ(nudge.steps, -3.0);
    EXPECT_EQ(std::get<NudgeSelected>(*bindingAction("nudge_selected", 2.0)).steps, 2.0);
    const auto page = std::get<PageSlice>(*bindingAction("page:sagittal", -2.0));
    EXPECT_EQ(page.axis, SliceAxis::Sagittal);
    EXPECT_EQ(page.delta, -2);
    // A fractional wheel step still pages one slice in its direction.
    EXPECT_EQ(std::get<PageSlice>(*bindingAction("page:axial", 0.2)).delta, 1);
    EXPECT_EQ(std::get<PageSlice>(*bindingAction("page:axial", -0.2)).delta, -1);
    EXPECT_EQ(std::get<PageSlice>(*bindingAction("page:axial", 1e300)).delta, 1000000);
    EXPECT_GT(std::get<RotateView>(*bindingAction("rotate_yaw", 1.0)).yaw, 0.0);
    EXPECT_GT(std::get<ZoomView>(*bindingAction("zoom", 1.0)).factor, 1.0);
    EXPECT_LT(std::get<ZoomView>(*bindingAction("zoom", -1.0)).factor, 1.0);
    EXPECT_EQ(std::get<CycleParam>(*bindingAction("cycle_param", -1.0)).delta, -1);
    EXPECT_TRUE(std::get<SetEraseMode>(*bindingAction("erase_mode:on", 1.0)).erase);
}

TEST(WorkflowAction, UnknownNamesAndNonFiniteStepsGiveNothing) {
    EXPECT_FALSE(bindingAction("", 1.0).has_value());
    EXPECT_FALSE(bindingAction("Run", 1.0).has_value());
    EXPECT_FALSE(bindingAction("nudge:X", 1.0).has_value());
    EXPECT_FALSE(bindingAction("load_scan", 1.0).has_value());
    EXPECT_FALSE(bindingAction("nudge:T", std::nan("")).has_value());
    EXPECT_FALSE(bindingAction("page:axial", INFINITY).has_value());
}

} // namespace
} // namespace steerseg::test
