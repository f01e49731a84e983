// A stroke through the kiosk's touch path without a GPU: pointer events -> the gesture
// recognizer -> Interaction -> the workflow over the in-memory engine. A one-finger drag paints
// along its path as one undo step; a second finger turns it into paging and paints nothing.
// In box mode a drag draws the box instead (docs/ui.md): one SetBox a drag, two drags on two
// orientations give all three axes, a drag on an edge moves that face, and a knob then moves it.
#include "render/slice_frame.hpp"
#include "support/workflow_rig.hpp"
#include "ui/gestures.hpp"
#include "ui/interaction.hpp"
#include "ui/panel_model.hpp"

#include <gtest/gtest.h>
#include <vector>

namespace steerseg::test {
namespace {

using Kind = platform::InputEvent::Kind;

// The fake engine's scan as the slice views show it: the first axial (its middle slice k = 4),
// the second coronal (slice j = 6).
ui::ScreenState fakeScreen() {
    Geometry g;
    g.dims = FakeEngine::defaultScan().dims;
    g.spacing = FakeEngine::defaultScan().spacing;
    ui::ScreenState s;
    s.layout = ui::computeLayout(1280, 800, 96.0);
    render::ViewParams p;
    p.kind = render::ViewKind::Axial;
    p.size = {s.layout.slice1.w, s.layout.slice1.h};
    p.slice = 4;
    s.slice1 = ui::SliceView{render::sliceFrame(g, p), p.size, s.layout.slice1};
    p.kind = render::ViewKind::Coronal;
    p.size = {s.layout.slice2.w, s.layout.slice2.h};
    p.slice = 6;
    s.slice2 = ui::SliceView{render::sliceFrame(g, p), p.size, s.layout.slice2};
    return s;
}

platform::InputEvent pointer(Kind kind, double time, glm::dvec2 at, int slot = 0) {
    platform::InputEvent e;
    e.kind = kind;
    e.time = time;
    e.pointer = slot;
    e.x = static_cast<float>(at.x);
    e.y = static_cast<float>(at.y);
    return e;
}

struct Touch {
    Rig rig;
    ui::ScreenState screen = fakeScreen();
    ui::GestureRecognizer gestures;
    ui::Interaction interaction;
    int strokes = 0;
    int pages = 0;
    int boxes = 0;                    // SetBox actions
    std::vector<model::Action> other; // every other action

    // One event through the whole path; every action it means goes to the workflow.
    void feed(const platform::InputEvent& e) {
        for (const ui::Gesture& g : gestures.feed(e)) {
            for (const model::Action& a : interaction.onGesture(g, screen, rig.status())) {
                strokes += std::holds_alternative<model::PaintStroke>(a) ? 1 : 0;
                pages += std::holds_alternative<model::PageSlice>(a) ? 1 : 0;
                boxes += std::holds_alternative<model::SetBox>(a) ? 1 : 0;
                if (!std::holds_alternative<model::SetBox>(a)) {
                    other.push_back(a);
                }
                const workflow::Workflow::Outcome out = rig.act(a);
                EXPECT_TRUE(out.accepted) << model::actionName(a) << ": " << out.reason;
            }
        }
    }
    glm::dvec2 at(const glm::dvec3& voxel) const {
        return ui::screenOfVoxel(*screen.slice1, voxel);
    }
    // A one-finger drag in four moves from `from` to `to` (screen points), lifted at `to`.
    void drag(glm::dvec2 from, glm::dvec2 to, double time = 0.0) {
        feed(pointer(Kind::PointerDown, time, from));
        for (int m = 1; m <= 4; ++m) {
            feed(pointer(Kind::PointerMove, time + 0.02 * m, from + (to - from) * (m / 4.0)));
            EXPECT_EQ(boxes, boxesBefore) << "no box before the finger lifts";
        }
        feed(pointer(Kind::PointerUp, time + 0.1, to));
    }
    int boxesBefore = 0;
};

model::Box boxOf(glm::ivec3 lo, glm::ivec3 hi) {
    return model::Box{lo, hi};
}

TEST(UiStrokeTouch, ADragPaintsAlongItsPathAsOneUndoStep) {
    Touch t;
    t.rig.driveTo(model::State::Paused);
    const std::size_t inside = t.rig.engine.insideVoxels();
    const std::size_t depth = t.rig.wf->undoDepth();
    // Down at (2, 2), then a fast drag in three moves to (13, 9): far apart, as a quick finger.
    const glm::dvec3 from(2.0, 2.0, 4.0);
    const glm::dvec3 to(13.0, 9.0, 4.0);
    t.feed(pointer(Kind::PointerDown, 0.0, t.at(from)));
    for (int m = 1; m <= 3; ++m) {
        t.feed(pointer(Kind::PointerMove, 0.02 * m, t.at(from + (to - from) * (m / 3.0))));
    }
    EXPECT_EQ(t.strokes, 0) << "nothing is painted before the finger lifts";
    EXPECT_EQ(t.rig.engine.insideVoxels(), inside);
    t.feed(pointer(Kind::PointerUp, 0.1, t.at(to)));
    EXPECT_EQ(t.strokes, 1);
    EXPECT_EQ(t.pages, 0);
    // Every voxel the path crosses is painted: no gap between the moves.
    for (int s = 0; s <= 40; ++s) {
        const glm::dvec3 p = from + (to - from) * (s / 40.0);
        EXPECT_TRUE(t.rig.engine.inside(glm::ivec3(glm::round(p)))) << p.x << ", " << p.y;
    }
    EXPECT_EQ(t.rig.wf->undoDepth(), depth + 1);
    ASSERT_TRUE(t.rig.act(model::Undo{}).accepted);
    EXPECT_EQ(t.rig.engine.insideVoxels(), inside) << "one undo takes the whole stroke back";
    EXPECT_FALSE(t.rig.engine.inside({2, 2, 4}));
}

TEST(UiStrokeTouch, ASecondFingerPagesAndPaintsNothing) {
    Touch t;
    t.rig.driveTo(model::State::Paused);
    const std::size_t inside = t.rig.engine.insideVoxels();
    const glm::dvec2 a = t.at({3.0, 3.0, 4.0});
    const glm::dvec2 b = t.at({12.0, 3.0, 4.0});
    t.feed(pointer(Kind::PointerDown, 0.0, a, 0));
    t.feed(pointer(Kind::PointerMove, 0.02, a + glm::dvec2(30.0, 0.0), 0)); // a stroke begins
    t.feed(pointer(Kind::PointerDown, 0.04, b, 1));
    for (int m = 1; m <= 5; ++m) { // both fingers up the screen together
        t.feed(pointer(Kind::PointerMove, 0.05 + 0.01 * m, a + glm::dvec2(30.0, -20.0 * m), 0));
        t.feed(pointer(Kind::PointerMove, 0.055 + 0.01 * m, b + glm::dvec2(0.0, -20.0 * m), 1));
    }
    t.feed(pointer(Kind::PointerUp, 0.2, a, 0));
    t.feed(pointer(Kind::PointerUp, 0.2, b, 1));
    EXPECT_EQ(t.strokes, 0);
    EXPECT_GT(t.pages, 0);
    EXPECT_EQ(t.rig.engine.insideVoxels(), inside);
    EXPECT_GT(t.rig.status().view.slice.x, 4) << "paged up through the axial slices";
}

// A box drawn on the axial view from (3, 2) to (10, 8): i and j as drawn; k, a first box's,
// as deep as its smaller side (7 mm: 3.5 of the fake's 2 mm slices), centred on slice 4.
TEST(UiBoxTouch, ADragInBoxModeOnTheAxialViewSetsOneBox) {
    Touch t;
    t.rig.load();
    ASSERT_TRUE(t.rig.act(model::SetBoxMode{true, std::nullopt}).accepted);
    const std::size_t depth = t.rig.wf->undoDepth();
    t.drag(t.at({3.0, 2.0, 4.0}), t.at({10.0, 8.0, 4.0}));
    EXPECT_EQ(t.boxes, 1);
    EXPECT_EQ(t.pages, 0);
    EXPECT_TRUE(t.other.empty());
    ASSERT_TRUE(t.rig.status().box.has_value());
    EXPECT_EQ(*t.rig.status().box, boxOf({3, 2, 3}, {10, 8, 5}));
    EXPECT_EQ(t.rig.state(), model::State::Seeding) << "the first box probes and seeds";
    EXPECT_EQ(t.rig.wf->undoDepth(), depth + 1) << "one drag, one undo step";
    EXPECT_FALSE(t.interaction.boxDraft().has_value()) << "the draft ends with the drag";
}

// Then a drag on the coronal view (j = 6) from (4, k 1) to (9, k 6) sets i and k; j keeps the
// box's extent. One SetBox again.
TEST(UiBoxTouch, ASecondDragOnTheCoronalViewSetsTheThirdAxis) {
    Touch t;
    t.rig.load();
    ASSERT_TRUE(t.rig.act(model::SetBoxMode{true, std::nullopt}).accepted);
    t.drag(t.at({3.0, 2.0, 4.0}), t.at({10.0, 8.0, 4.0}));
    ASSERT_EQ(t.boxes, 1);
    t.boxesBefore = 1;
    const ui::SliceView& coronal = *t.screen.slice2;
    const glm::dvec2 from = ui::screenOfVoxel(coronal, {4.0, 6.0, 1.0});
    const glm::dvec2 to = ui::screenOfVoxel(coronal, {9.0, 6.0, 6.0});
    // While the finger moves, the draft already is the box it will set.
    t.feed(pointer(Kind::PointerDown, 1.0, from));
    t.feed(pointer(Kind::PointerMove, 1.05, to));
    ASSERT_TRUE(t.interaction.boxDraft().has_value());
    EXPECT_EQ(*t.interaction.boxDraft(), boxOf({4, 2, 1}, {9, 8, 6}));
    EXPECT_EQ(t.boxes, 1);
    t.feed(pointer(Kind::PointerUp, 1.1, to));
    EXPECT_EQ(t.boxes, 2);
    ASSERT_TRUE(t.rig.status().box.has_value());
    EXPECT_EQ(*t.rig.status().box, boxOf({4, 2, 1}, {9, 8, 6}));
}

// A drag begun on the box's right edge (i = 11.5 on the axial view) moves that face alone, by
// the finger's travel, and makes it the knob's: a detent (the knob's binding, nudge_selected)
// moves it one voxel; selecting a parameter gives the knob back to it.
TEST(UiBoxTouch, AFaceDragMovesOneFaceAndTheKnobMovesItOn) {
    Touch t;
    t.rig.driveTo(model::State::Paused);
    const model::Box box = boxOf({4, 2, 1}, {11, 9, 6});
    ASSERT_TRUE(t.rig.act(model::SetBox{box}).accepted);
    ASSERT_TRUE(t.rig.act(model::SetBoxMode{true, std::nullopt}).accepted);
    const std::size_t depth = t.rig.wf->undoDepth();
    t.drag(t.at({11.5, 5.0, 4.0}), t.at({13.5, 5.0, 4.0}));
    EXPECT_EQ(t.boxes, 1);
    EXPECT_EQ(*t.rig.status().box, boxOf({4, 2, 1}, {13, 9, 6})) << "only i's high face moved";
    EXPECT_EQ(t.rig.status().boxFace, (model::BoxFace{0, true}));
    EXPECT_EQ(t.rig.wf->undoDepth(), depth + 1);

    const std::optional<model::Action> detent = model::bindingAction("nudge_selected", 1.0);
    ASSERT_TRUE(detent.has_value());
    const float T = t.rig.status().params.T;
    ASSERT_TRUE(t.rig.act(*detent).accepted);
    EXPECT_EQ(*t.rig.status().box, boxOf({4, 2, 1}, {14, 9, 6}));
    ASSERT_TRUE(t.rig.act(*model::bindingAction("nudge_selected", -3.0)).accepted);
    EXPECT_EQ(*t.rig.status().box, boxOf({4, 2, 1}, {11, 9, 6}));
    EXPECT_EQ(t.rig.status().params.T, T) << "the knob moved the face, not T";
    // At the scan's border the face stops there.
    ASSERT_TRUE(t.rig.act(*model::bindingAction("nudge_selected", 50.0)).accepted);
    EXPECT_EQ(t.rig.status().box->hi.x, 15);
    ASSERT_TRUE(t.rig.act(model::Undo{}).accepted);
    EXPECT_EQ(t.rig.status().box->hi.x, 11) << "each detent one undo step";

    ASSERT_TRUE(t.rig.act(model::SelectParam{model::Param::T}).accepted);
    EXPECT_FALSE(t.rig.status().boxFace.has_value());
    ASSERT_TRUE(t.rig.act(*detent).accepted);
    EXPECT_EQ(t.rig.status().box->hi.x, 11);
    EXPECT_NE(t.rig.status().params.T, T) << "the knob drives T again";
}

// A drag begun inside the box, away from its edges, draws a new extent on the view's axes.
TEST(UiBoxTouch, ADragAwayFromTheEdgesDrawsANewExtent) {
    Touch t;
    t.rig.driveTo(model::State::Paused);
    ASSERT_TRUE(t.rig.act(model::SetBox{boxOf({2, 1, 1}, {13, 10, 6})}).accepted);
    ASSERT_TRUE(t.rig.act(model::SetBoxMode{true, std::nullopt}).accepted);
    t.drag(t.at({6.0, 5.0, 4.0}), t.at({9.0, 8.0, 4.0}));
    EXPECT_EQ(t.boxes, 1);
    EXPECT_EQ(*t.rig.status().box, boxOf({6, 5, 1}, {9, 8, 6})) << "k keeps the box's extent";
    EXPECT_FALSE(t.rig.status().boxFace.has_value());
}

// Box mode: a tap and a long press change nothing; out of box mode the same drag paints.
TEST(UiBoxTouch, ATapInBoxModeDoesNothingAndADragOutOfItPaints) {
    Touch t;
    t.rig.driveTo(model::State::Paused);
    ASSERT_TRUE(t.rig.act(model::SetBoxMode{true, std::nullopt}).accepted);
    const std::size_t inside = t.rig.engine.insideVoxels();
    const int seeds = t.rig.status().seeds;
    const glm::dvec2 p = t.at({3.0, 3.0, 4.0});
    t.feed(pointer(Kind::PointerDown, 0.0, p));
    t.feed(pointer(Kind::PointerUp, 0.05, p));
    for (const ui::Gesture& g : t.gestures.feed(pointer(Kind::PointerDown, 1.0, p))) {
        EXPECT_TRUE(t.interaction.onGesture(g, t.screen, t.rig.status()).empty());
    }
    for (const ui::Gesture& g : t.gestures.update(2.0)) { // a long press
        EXPECT_TRUE(t.interaction.onGesture(g, t.screen, t.rig.status()).empty());
    }
    t.feed(pointer(Kind::PointerUp, 2.1, p));
    EXPECT_TRUE(t.other.empty());
    EXPECT_EQ(t.boxes, 0);
    EXPECT_EQ(t.rig.status().seeds, seeds);
    EXPECT_EQ(t.rig.engine.insideVoxels(), inside);

    ASSERT_TRUE(t.rig.act(model::SetBoxMode{false, std::nullopt}).accepted);
    t.drag(t.at({2.0, 2.0, 4.0}), t.at({13.0, 9.0, 4.0}), 3.0);
    EXPECT_EQ(t.strokes, 1);
    EXPECT_EQ(t.boxes, 0);
}

// One meaning per tap: the panel's box toggle turns erase and outside modes off, and either of
// them turns box mode off (and forgets the knob's face).
TEST(UiBoxTouch, BoxModeAndEraseOrOutsideModeExcludeEachOther) {
    Touch t;
    t.rig.driveTo(model::State::Paused);
    ASSERT_TRUE(t.rig.act(model::SetSpeed{model::SpeedKind::Classify}).accepted);
    const auto press = [&](const std::string& label) {
        const ui::PanelModel m = ui::buildPanelModel(t.rig.status(), {});
        for (const auto* list : {&m.tools, &m.exampleTools}) {
            for (const ui::PanelButton& b : *list) {
                if (b.label == label) {
                    ASSERT_TRUE(t.rig.act(b.action).accepted) << label;
                    return;
                }
            }
        }
        FAIL() << "no button " << label;
    };
    press("Erase: off");
    EXPECT_TRUE(t.rig.status().eraseMode);
    press("Box: off");
    EXPECT_TRUE(t.rig.status().boxMode);
    EXPECT_FALSE(t.rig.status().eraseMode);
    press("Erase: off");
    EXPECT_FALSE(t.rig.status().boxMode);
    press("Box: off");
    press("Outside: off");
    EXPECT_FALSE(t.rig.status().boxMode);
    EXPECT_TRUE(t.rig.status().outsideMode);
    ASSERT_TRUE(t.rig.act(model::SetBoxMode{true, model::BoxFace{2, false}}).accepted);
    EXPECT_FALSE(t.rig.status().outsideMode);
    EXPECT_FALSE(t.rig.status().eraseMode);
    ASSERT_TRUE(t.rig.act(model::SetEraseMode{true}).accepted);
    EXPECT_FALSE(t.rig.status().boxFace.has_value()) << "the knob goes back to the parameter";
    press("Erase: on");
    EXPECT_FALSE(t.rig.status().eraseMode);
    EXPECT_FALSE(t.rig.status().boxMode);
}

} // namespace
} // namespace steerseg::test
