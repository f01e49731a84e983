// A stroke through the kiosk's touch path without a GPU: pointer events -> the gesture
// recognizer -> Interaction -> the workflow over the in-memory engine. A one-finger drag paints
// along its path as one undo step; a second finger turns it into paging and paints nothing.
#include "render/slice_frame.hpp"
#include "support/workflow_rig.hpp"
#include "ui/gestures.hpp"
#include "ui/interaction.hpp"

#include <gtest/gtest.h>
#include <vector>

namespace steerseg::test {
namespace {

using Kind = platform::InputEvent::Kind;

// The fake engine's scan as the first slice view shows it (axial, its middle slice k = 4).
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

    // One event through the whole path; every action it means goes to the workflow.
    void feed(const platform::InputEvent& e) {
        for (const ui::Gesture& g : gestures.feed(e)) {
            for (const model::Action& a : interaction.onGesture(g, screen, rig.status())) {
                strokes += std::holds_alternative<model::PaintStroke>(a) ? 1 : 0;
                pages += std::holds_alternative<model::PageSlice>(a) ? 1 : 0;
                const workflow::Workflow::Outcome out = rig.act(a);
                EXPECT_TRUE(out.accepted) << model::actionName(a) << ": " << out.reason;
            }
        }
    }
    glm::dvec2 at(const glm::dvec3& voxel) const {
        return ui::screenOfVoxel(*screen.slice1, voxel);
    }
};

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

} // namespace
} // namespace steerseg::test
