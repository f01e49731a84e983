#include "render/slice_frame.hpp"
#include "ui/interaction.hpp"

#include <cmath>
#include <gtest/gtest.h>

namespace steerseg::test {

using model::Action;
using model::State;

namespace {

Geometry geometry() {
    Geometry g;
    g.dims = {64, 48, 40};
    g.spacing = {1.0, 1.0, 2.0};
    return g;
}

ui::SliceView view(render::ViewKind kind, const ui::Rect& rect) {
    render::ViewParams p;
    p.kind = kind;
    p.size = {rect.w / 2, rect.h / 2};
    return {render::sliceFrame(geometry(), p), p.size, rect};
}

ui::ScreenState screen() {
    ui::ScreenState s;
    s.layout = ui::computeLayout(1280, 800, 96.0);
    s.slice1 = view(render::ViewKind::Axial, s.layout.slice1);
    s.slice2 = view(render::ViewKind::Coronal, s.layout.slice2);
    return s;
}

workflow::Status status(State state) {
    workflow::Status st;
    st.state = state;
    st.scan.dims = geometry().dims;
    st.view.first = model::SliceAxis::Axial;
    st.view.second = model::SliceAxis::Coronal;
    return st;
}

ui::Gesture gesture(ui::Gesture::Kind kind, glm::dvec2 at, int id = 1) {
    ui::Gesture g;
    g.kind = kind;
    g.id = id;
    g.start = at;
    g.position = at;
    return g;
}

glm::dvec2 centreOf(const ui::Rect& r) {
    return {r.x + 0.5 * r.w, r.y + 0.5 * r.h};
}

int pagedBy(const std::vector<Action>& actions, model::SliceAxis axis) {
    int total = 0;
    for (const Action& a : actions) {
        const auto* p = std::get_if<model::PageSlice>(&a);
        EXPECT_NE(p, nullptr);
        if (p != nullptr) {
            EXPECT_EQ(p->axis, axis);
            total += p->delta;
        }
    }
    return total;
}

} // namespace

TEST(UiInteraction, TapInInspectProbesTheVoxelUnderTheFinger) {
    ui::InteractionConfig config;
    config.probeRadiusMm = 7.5;
    ui::Interaction in(config);
    const ui::ScreenState s = screen();
    const glm::dvec2 at = centreOf(s.layout.slice1) + glm::dvec2(13.0, -7.0);
    const auto out = in.onGesture(gesture(ui::Gesture::Kind::Tap, at), s, status(State::Inspect));
    ASSERT_EQ(out.size(), 1U);
    const auto* probe = std::get_if<model::Probe>(&out[0]);
    ASSERT_NE(probe, nullptr);
    EXPECT_EQ(probe->radiusMm, 7.5);
    EXPECT_NEAR(glm::length(probe->voxel - *ui::voxelAtScreen(*s.slice1, at)), 0.0, 1e-12);
    // Axial: k is the slice axis and the tap stays on the shown slice.
    EXPECT_EQ(probe->voxel.z, s.slice1->frame.slice);
    // A long press in Inspect is not a probe.
    EXPECT_TRUE(
        in.onGesture(gesture(ui::Gesture::Kind::LongPress, at), s, status(State::Inspect)).empty());
}

TEST(UiInteraction, TapSeedsOrErasesWhileEditing) {
    ui::Interaction in;
    const ui::ScreenState s = screen();
    const glm::dvec2 at = centreOf(s.layout.slice2);
    for (State state : {State::Seeding, State::Evolving, State::Paused}) {
        const auto seed = in.onGesture(gesture(ui::Gesture::Kind::Tap, at), s, status(state));
        ASSERT_EQ(seed.size(), 1U);
        const auto* add = std::get_if<model::AddSeed>(&seed[0]);
        ASSERT_NE(add, nullptr);
        EXPECT_LE(add->radius, 0.0) << "the brush radius";
        EXPECT_NEAR(glm::length(add->voxel - *ui::voxelAtScreen(*s.slice2, at)), 0.0, 1e-12);

        workflow::Status erasing = status(state);
        erasing.eraseMode = true;
        const auto erase = in.onGesture(gesture(ui::Gesture::Kind::Tap, at), s, erasing);
        ASSERT_EQ(erase.size(), 1U);
        EXPECT_TRUE(std::holds_alternative<model::Erase>(erase[0]));

        const auto held = in.onGesture(gesture(ui::Gesture::Kind::LongPress, at), s, status(state));
        ASSERT_EQ(held.size(), 1U);
        EXPECT_TRUE(std::holds_alternative<model::Erase>(held[0]));
    }
    for (State state : {State::NoScan, State::Loading, State::Review, State::Exporting, State::Done,
                        State::Error}) {
        EXPECT_TRUE(in.onGesture(gesture(ui::Gesture::Kind::Tap, at), s, status(state)).empty())
            << static_cast<int>(state);
    }
}

TEST(UiInteraction, TapInOutsideModeMarksAnOutsideExample) {
    ui::InteractionConfig config;
    config.probeRadiusMm = 6.0;
    ui::Interaction in(config);
    const ui::ScreenState s = screen();
    const glm::dvec2 at = centreOf(s.layout.slice1);
    for (State state : {State::Inspect, State::Seeding, State::Evolving, State::Paused}) {
        workflow::Status st = status(state);
        st.outsideMode = true;
        const auto out = in.onGesture(gesture(ui::Gesture::Kind::Tap, at), s, st);
        ASSERT_EQ(out.size(), 1U) << static_cast<int>(state);
        const auto* mark = std::get_if<model::MarkOutside>(&out[0]);
        ASSERT_NE(mark, nullptr) << static_cast<int>(state);
        EXPECT_EQ(mark->radiusMm, 6.0) << "sized as a probe";
        EXPECT_NEAR(glm::length(mark->voxel - *ui::voxelAtScreen(*s.slice1, at)), 0.0, 1e-12);
        if (state != State::Inspect) {
            // A long press still erases: outside mode changes the tap only.
            const auto held = in.onGesture(gesture(ui::Gesture::Kind::LongPress, at), s, st);
            ASSERT_EQ(held.size(), 1U);
            EXPECT_TRUE(std::holds_alternative<model::Erase>(held[0]));
        }
    }
    for (State state : {State::Review, State::Done, State::Error}) {
        workflow::Status st = status(state);
        st.outsideMode = true;
        EXPECT_TRUE(in.onGesture(gesture(ui::Gesture::Kind::Tap, at), s, st).empty())
            << static_cast<int>(state);
    }
}

TEST(UiInteraction, TapBesideTheScanOrOnThePanelDoesNothing) {
    ui::Interaction in;
    const ui::ScreenState s = screen();
    // The axial slice is 64 x 48 mm in a taller rect: the top rows are letterbox.
    const glm::dvec2 top(centreOf(s.layout.slice1).x, s.layout.slice1.y + 2.0);
    EXPECT_TRUE(
        in.onGesture(gesture(ui::Gesture::Kind::Tap, top), s, status(State::Seeding)).empty());
    EXPECT_TRUE(in.onGesture(gesture(ui::Gesture::Kind::Tap, centreOf(s.layout.panel)), s,
                             status(State::Seeding))
                    .empty());
    EXPECT_TRUE(in.onGesture(gesture(ui::Gesture::Kind::Tap, centreOf(s.layout.view3d)), s,
                             status(State::Seeding))
                    .empty());
}

TEST(UiInteraction, VerticalDragOnASlicePagesWhereATapPlacesNoSphere) {
    ui::InteractionConfig config;
    config.pxPerSlice = 10.0;
    ui::Interaction in(config);
    const ui::ScreenState s = screen();
    ui::Gesture g = gesture(ui::Gesture::Kind::Drag, centreOf(s.layout.slice1), 7);
    std::vector<Action> all;
    for (int i = 0; i < 7; ++i) {
        g.delta = {1.0, -5.0}; // up, 35 px in all
        for (const Action& a : in.onGesture(g, s, status(State::Review))) {
            all.push_back(a);
        }
    }
    g.delta = {0.0, 0.0};
    g.lifted = true;
    EXPECT_TRUE(in.onGesture(g, s, status(State::Review)).empty());
    EXPECT_EQ(pagedBy(all, model::SliceAxis::Axial), 3);
    // A new drag starts from no remainder; down pages back, on the second view's axis.
    ui::Gesture down = gesture(ui::Gesture::Kind::Drag, centreOf(s.layout.slice2), 8);
    down.delta = {0.0, 25.0};
    EXPECT_EQ(pagedBy(in.onGesture(down, s, status(State::Inspect)), model::SliceAxis::Coronal),
              -2);
}

// A one-finger drag in `state` from `from` by `steps` moves of `step` px, then the lift.
std::vector<Action> drag(ui::Interaction& in, const ui::ScreenState& s, const workflow::Status& st,
                         glm::dvec2 from, glm::dvec2 step, int steps) {
    static int id = 100; // each drag is a gesture of its own
    std::vector<Action> out;
    ui::Gesture g = gesture(ui::Gesture::Kind::Drag, from, ++id);
    for (int i = 1; i <= steps; ++i) {
        g.position = from + static_cast<double>(i) * step;
        g.delta = step;
        for (Action& a : in.onGesture(g, s, st)) {
            out.push_back(std::move(a));
        }
        EXPECT_TRUE(out.empty()) << "nothing is painted before the finger lifts";
    }
    g.delta = {0.0, 0.0};
    g.lifted = true;
    for (Action& a : in.onGesture(g, s, st)) {
        out.push_back(std::move(a));
    }
    return out;
}

TEST(UiInteraction, ADragPaintsOneStrokeWhenTheFingerLifts) {
    ui::Interaction in;
    const ui::ScreenState s = screen();
    const glm::dvec2 from = centreOf(s.layout.slice1) - glm::dvec2(60.0, 0.0);
    for (State state : {State::Seeding, State::Evolving, State::Paused}) {
        const auto out = drag(in, s, status(state), from, {12.0, 3.0}, 10);
        ASSERT_EQ(out.size(), 1U) << static_cast<int>(state);
        const auto* stroke = std::get_if<model::PaintStroke>(&out[0]);
        ASSERT_NE(stroke, nullptr);
        EXPECT_EQ(stroke->mode, model::StrokeMode::Add);
        EXPECT_LE(stroke->radius, 0.0) << "the brush radius";
        ASSERT_EQ(stroke->points.size(), 11U) << "where it went down, and each move";
        EXPECT_NEAR(glm::length(stroke->points.front() - *ui::voxelAtScreen(*s.slice1, from)), 0.0,
                    1e-12);
        const glm::dvec2 end = from + 10.0 * glm::dvec2(12.0, 3.0);
        EXPECT_NEAR(glm::length(stroke->points.back() - *ui::voxelAtScreen(*s.slice1, end)), 0.0,
                    1e-12);
        for (const glm::dvec3& p : stroke->points) {
            EXPECT_EQ(p.z, s.slice1->frame.slice) << "on the shown slice";
        }
        EXPECT_TRUE(in.strokePath().empty()) << "the stroke is over";
    }
    workflow::Status erasing = status(State::Paused);
    erasing.eraseMode = true;
    auto out = drag(in, s, erasing, from, {12.0, 0.0}, 3);
    ASSERT_EQ(out.size(), 1U);
    EXPECT_EQ(std::get<model::PaintStroke>(out[0]).mode, model::StrokeMode::Erase);
    for (State state : {State::Inspect, State::Seeding}) {
        workflow::Status outside = status(state);
        outside.outsideMode = true;
        out = drag(in, s, outside, from, {12.0, 0.0}, 3);
        ASSERT_EQ(out.size(), 1U);
        EXPECT_EQ(std::get<model::PaintStroke>(out[0]).mode, model::StrokeMode::Outside);
    }
}

TEST(UiInteraction, TheStrokeIsDrawnWhileTheFingerIsDown) {
    ui::Interaction in;
    const ui::ScreenState s = screen();
    const glm::dvec2 from = centreOf(s.layout.slice2);
    ui::Gesture g = gesture(ui::Gesture::Kind::Drag, from, 3);
    g.position = from + glm::dvec2(20.0, 0.0);
    EXPECT_TRUE(in.onGesture(g, s, status(State::Paused)).empty());
    EXPECT_EQ(in.strokePath(), (std::vector<glm::dvec2>{from, g.position}));
    EXPECT_EQ(in.strokeMode(), model::StrokeMode::Add);
}

TEST(UiInteraction, ASecondFingerCancelsTheStrokeAndPages) {
    ui::InteractionConfig config;
    config.pxPerSlice = 10.0;
    ui::Interaction in(config);
    const ui::ScreenState s = screen();
    const glm::dvec2 at = centreOf(s.layout.slice1);
    ui::Gesture g = gesture(ui::Gesture::Kind::Drag, at, 4);
    g.position = at + glm::dvec2(30.0, 0.0);
    EXPECT_TRUE(in.onGesture(g, s, status(State::Seeding)).empty());
    EXPECT_FALSE(in.strokePath().empty());
    // The second finger: a pinch, whose centre's motion pages (two fingers page in every mode).
    ui::Gesture pinch = gesture(ui::Gesture::Kind::Pinch, at, 5);
    std::vector<Action> paged;
    for (int i = 0; i < 3; ++i) {
        pinch.delta = {0.0, -10.0};
        for (Action& a : in.onGesture(pinch, s, status(State::Seeding))) {
            paged.push_back(std::move(a));
        }
    }
    EXPECT_TRUE(in.strokePath().empty()) << "nothing is painted";
    EXPECT_EQ(pagedBy(paged, model::SliceAxis::Axial), 3);
}

TEST(UiInteraction, ALongScribbleIsSentInStrokesOfAtMostTheLimit) {
    ui::Interaction in;
    const ui::ScreenState s = screen();
    const workflow::Status st = status(State::Paused);
    const glm::dvec2 at = centreOf(s.layout.slice1) - glm::dvec2(60.0, 0.0);
    std::vector<Action> out;
    ui::Gesture g = gesture(ui::Gesture::Kind::Drag, at, 9);
    for (std::size_t i = 1; i <= model::kMaxStrokePoints + 10; ++i) {
        // Back and forth over 120 px: every move lands on another voxel.
        g.position = at + glm::dvec2(i % 2 == 1 ? 120.0 : 0.0, 0.0);
        for (Action& a : in.onGesture(g, s, st)) {
            out.push_back(std::move(a));
        }
    }
    ASSERT_EQ(out.size(), 1U) << "the first stroke went when it was full";
    const auto& first = std::get<model::PaintStroke>(out[0]);
    EXPECT_EQ(first.points.size(), model::kMaxStrokePoints);
    g.lifted = true;
    const auto rest = in.onGesture(g, s, st);
    ASSERT_EQ(rest.size(), 1U);
    const auto& second = std::get<model::PaintStroke>(rest[0]);
    EXPECT_EQ(second.points.front(), first.points.back()) << "the next goes on where it ended";
}

TEST(UiInteraction, WheelOnASlicePagesAndCarriesFractions) {
    ui::Interaction in;
    const ui::ScreenState s = screen();
    ui::Gesture w = gesture(ui::Gesture::Kind::Wheel, centreOf(s.layout.slice1));
    w.wheel = 2.0;
    EXPECT_EQ(pagedBy(in.onGesture(w, s, status(State::Paused)), model::SliceAxis::Axial), 2);
    w.wheel = 0.5;
    EXPECT_TRUE(in.onGesture(w, s, status(State::Paused)).empty());
    EXPECT_EQ(pagedBy(in.onGesture(w, s, status(State::Paused)), model::SliceAxis::Axial), 1);
}

TEST(UiInteraction, DragRotatesAndPinchOrWheelZoomsThe3dView) {
    ui::InteractionConfig config;
    config.degreesPerPx = 0.5;
    config.zoomPerDetent = 1.25;
    ui::Interaction in(config);
    const ui::ScreenState s = screen();
    ui::Gesture drag = gesture(ui::Gesture::Kind::Drag, centreOf(s.layout.view3d));
    drag.delta = {10.0, -4.0};
    const auto rotate = in.onGesture(drag, s, status(State::Review));
    ASSERT_EQ(rotate.size(), 1U);
    const auto* r = std::get_if<model::RotateView>(&rotate[0]);
    ASSERT_NE(r, nullptr);
    EXPECT_DOUBLE_EQ(r->yaw, 5.0);
    EXPECT_DOUBLE_EQ(r->pitch, -2.0);

    ui::Gesture pinch = gesture(ui::Gesture::Kind::Pinch, centreOf(s.layout.view3d));
    pinch.scale = 1.5;
    const auto zoom = in.onGesture(pinch, s, status(State::Inspect));
    ASSERT_EQ(zoom.size(), 1U);
    EXPECT_DOUBLE_EQ(std::get<model::ZoomView>(zoom[0]).factor, 1.5);

    ui::Gesture wheel = gesture(ui::Gesture::Kind::Wheel, centreOf(s.layout.view3d));
    wheel.wheel = -2.0;
    const auto out = in.onGesture(wheel, s, status(State::Evolving));
    ASSERT_EQ(out.size(), 1U);
    EXPECT_NEAR(std::get<model::ZoomView>(out[0]).factor, 1.0 / (1.25 * 1.25), 1e-12);

    EXPECT_TRUE(in.onGesture(drag, s, status(State::NoScan)).empty());
    pinch.scale = std::nan("");
    EXPECT_TRUE(in.onGesture(pinch, s, status(State::Inspect)).empty());
}

TEST(UiInteraction, ConfigFromDpi) {
    const ui::InteractionConfig c = ui::interactionConfig(254.0, 4.0);
    EXPECT_NEAR(c.pxPerSlice, 15.0, 1e-9);
    EXPECT_EQ(c.probeRadiusMm, 4.0);
    EXPECT_EQ(ui::interactionConfig(96.0, -1.0).probeRadiusMm,
              ui::InteractionConfig{}.probeRadiusMm);
}

} // namespace steerseg::test
