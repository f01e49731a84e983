#include "exports/image_file.hpp"
#include "gpu/gl_handle.hpp"
#include "model/structure.hpp"
#include "render/slice_frame.hpp"
#include "support/gpu_fixture.hpp"
#include "support/workflow_rig.hpp"
#include "ui/imgui_layer.hpp"
#include "ui/layout.hpp"
#include "ui/overlays.hpp"
#include "ui/panel.hpp"
#include "ui/touch_ui.hpp"

#include <array>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <gtest/gtest.h>
#include <tuple>
#include <vector>

namespace steerseg::test {

using model::Action;
using model::State;

namespace {

constexpr int kW = 1280;
constexpr int kH = 800;
constexpr std::array<std::uint8_t, 4> kBackground{255, 0, 255, 255};

// A 1280x800 RGBA8 colour target, bound for drawing while it lives.
class Screen {
  public:
    Screen() : texture_(gpu::createTexture()) {
        glBindTexture(GL_TEXTURE_2D, texture_.id());
        glTexStorage2D(GL_TEXTURE_2D, 1, GL_RGBA8, kW, kH);
        GLuint fb = 0;
        glGenFramebuffers(1, &fb);
        framebuffer_ = gpu::Framebuffer(fb);
        glBindFramebuffer(GL_FRAMEBUFFER, fb);
        glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, texture_.id(),
                               0);
        EXPECT_EQ(glCheckFramebufferStatus(GL_FRAMEBUFFER),
                  static_cast<GLenum>(GL_FRAMEBUFFER_COMPLETE));
        glViewport(0, 0, kW, kH);
    }
    ~Screen() { glBindFramebuffer(GL_FRAMEBUFFER, 0); }
    Screen(const Screen&) = delete;
    Screen& operator=(const Screen&) = delete;

    static void clear() {
        glClearColor(1.0F, 0.0F, 1.0F, 1.0F);
        glClear(GL_COLOR_BUFFER_BIT);
    }
    // Rows top first (GL's are bottom first).
    [[nodiscard]] std::vector<std::uint8_t> read() const {
        std::vector<std::uint8_t> gl(static_cast<std::size_t>(kW) * kH * 4);
        glBindFramebuffer(GL_READ_FRAMEBUFFER, framebuffer_.id());
        glPixelStorei(GL_PACK_ALIGNMENT, 1);
        glReadPixels(0, 0, kW, kH, GL_RGBA, GL_UNSIGNED_BYTE, gl.data());
        std::vector<std::uint8_t> top(gl.size());
        const std::size_t row = static_cast<std::size_t>(kW) * 4;
        for (int y = 0; y < kH; ++y) {
            std::copy_n(gl.begin() + static_cast<std::ptrdiff_t>(row * (kH - 1 - y)), row,
                        top.begin() + static_cast<std::ptrdiff_t>(row * y));
        }
        return top;
    }

  private:
    gpu::Texture texture_;
    gpu::Framebuffer framebuffer_;
};

// Pixels of `r` that are not the background, and those that are near white (text).
struct Counts {
    long changed = 0;
    long white = 0;
    long total = 0;
};
Counts count(const std::vector<std::uint8_t>& px, const ui::Rect& r) {
    Counts c;
    for (int y = r.y; y < r.y + r.h; ++y) {
        for (int x = r.x; x < r.x + r.w; ++x) {
            const std::uint8_t* p = &px[(static_cast<std::size_t>(y) * kW + x) * 4];
            ++c.total;
            if (p[0] != kBackground[0] || p[1] != kBackground[1] || p[2] != kBackground[2]) {
                ++c.changed;
            }
            if (p[0] > 200 && p[1] > 200 && p[2] > 200) {
                ++c.white;
            }
        }
    }
    return c;
}

workflow::Status status(State state) {
    workflow::Status st;
    st.state = state;
    st.scan.name = "sample";
    st.scan.units = "HU";
    st.scan.dims = {64, 64, 48};
    st.scan.minValue = -1000.0;
    st.scan.maxValue = 1000.0;
    st.params.T = 40.0F;
    st.params.eps = 30.0F;
    st.presets = {"CT soft tissue", "CT bone"};
    st.canUndo = true;
    st.message = state == State::Error ? "scan.nii: not a NIfTI file" : "";
    st.loadProgress = 0.3;
    return st;
}

const std::vector<std::string> kScans{"builtin:sample", "/data/CT_sarcoma.nii.gz"};

class UiPanel : public GpuTest {
  protected:
    // One frame of the panel (and the captions); returns its actions.
    std::vector<Action> frame(ui::ImGuiLayer& layer, const workflow::Status& st,
                              const ui::ScreenState* screen = nullptr) {
        time_ += 1.0 / 30.0;
        layer.beginFrame({kW, kH}, time_);
        std::vector<Action> out = panel_.draw(layer, st, layout_.panel, kScans);
        if (screen != nullptr) {
            ui::drawViewCaptions(layer, *screen, st);
        }
        layer.endFrame();
        return out;
    }

    static platform::InputEvent pointer(platform::InputEvent::Kind kind, glm::dvec2 at) {
        platform::InputEvent e;
        e.kind = kind;
        e.x = static_cast<float>(at.x);
        e.y = static_cast<float>(at.y);
        return e;
    }

    // Taps the middle of a widget: down and up fed at once, as a touchscreen delivers a quick
    // tap within one frame; returns every action of the frames that follow.
    std::vector<Action> tap(ui::ImGuiLayer& layer, const workflow::Status& st,
                            const std::string& label) {
        frame(layer, st);
        const std::optional<ui::Rect> r = panel_.widgetRect(label);
        EXPECT_TRUE(r) << label;
        if (!r) {
            return {};
        }
        const glm::dvec2 at(r->x + 0.5 * r->w, r->y + 0.5 * r->h);
        layer.feed(pointer(platform::InputEvent::Kind::PointerDown, at));
        layer.feed(pointer(platform::InputEvent::Kind::PointerUp, at));
        std::vector<Action> all;
        for (int i = 0; i < 3; ++i) {
            for (const Action& a : frame(layer, st)) {
                all.push_back(a);
            }
        }
        return all;
    }

    ui::Layout layout_ = ui::computeLayout(kW, kH, 96.0);
    ui::Panel panel_;
    double time_ = 0.0;
};

} // namespace

TEST_F(UiPanel, DrawsInsideThePanelForEachState) {
    Screen screen;
    ui::ImGuiLayer layer;
    // Where fonts-dejavu-core is installed (tools/install-deps.sh, the .deb's dependency) the
    // panel uses it; a machine without it (the lent GPU machine) draws with ImGui's own.
    EXPECT_EQ(layer.fallbackFont(), !std::filesystem::exists(ui::kDefaultFontPath))
        << ui::kDefaultFontPath;
    for (State state : {State::NoScan, State::Loading, State::Inspect, State::Seeding,
                        State::Evolving, State::Review, State::Done, State::Error}) {
        SCOPED_TRACE(static_cast<int>(state));
        const workflow::Status st = status(state);
        frame(layer, st); // ImGui sizes its windows on the first frame
        Screen::clear();
        EXPECT_TRUE(frame(layer, st).empty()) << "no touch, no action";
        const std::vector<std::uint8_t> px = screen.read();
        // STEERSEG_UI_SNAPSHOTS=<folder>: the frames as PNG, to look at the panel.
        if (const char* dir = std::getenv("STEERSEG_UI_SNAPSHOTS")) {
            exports::writeImage(std::filesystem::path(dir) /
                                    ("panel_" + ui::stateLabel(state) + ".png"),
                                RgbaImage{kW, kH, px});
        }
        const Counts in = count(px, layout_.panel);
        EXPECT_GT(in.changed, in.total * 9 / 10) << "the panel's background covers its rect";
        EXPECT_GT(in.white, 200) << "the banner's text";
        const Counts out = count(px, layout_.view3d);
        EXPECT_EQ(out.changed, 0) << "nothing drawn over the 3D view";
        // Every button and slider at least the touch target.
        EXPECT_EQ(panel_.widgetRects().empty(), state == State::Loading);
        for (const auto& [label, r] : panel_.widgetRects()) {
            EXPECT_GE(r.h + 1, static_cast<int>(layer.touchPx())) << label;
            EXPECT_GE(r.w + 1, static_cast<int>(layer.touchPx())) << label;
        }
    }
}

TEST_F(UiPanel, TapOnRunInSeedingEmitsRun) {
    Screen screen;
    ui::ImGuiLayer layer;
    const std::vector<Action> out = tap(layer, status(State::Seeding), "Run");
    ASSERT_EQ(out.size(), 1U);
    EXPECT_TRUE(std::holds_alternative<model::Run>(out[0]));
}

TEST_F(UiPanel, TapsOnProceedPlusAndALoadButton) {
    Screen screen;
    ui::ImGuiLayer layer;
    const std::vector<Action> seed = tap(layer, status(State::Inspect), "Seed##proceed");
    ASSERT_EQ(seed.size(), 1U);
    EXPECT_TRUE(std::holds_alternative<model::Proceed>(seed[0]));

    const std::vector<Action> plus = tap(layer, status(State::Paused), "+##eps");
    ASSERT_EQ(plus.size(), 1U);
    const auto* nudge = std::get_if<model::NudgeParam>(&plus[0]);
    ASSERT_NE(nudge, nullptr);
    EXPECT_EQ(nudge->param, model::Param::Eps);
    EXPECT_EQ(nudge->steps, 1.0);

    const std::vector<Action> load = tap(layer, status(State::NoScan), "Load Sample##scan0");
    ASSERT_EQ(load.size(), 1U);
    EXPECT_EQ(std::get<model::LoadScan>(load[0]).path, "builtin:sample");
}

TEST_F(UiPanel, WantsThePointerOverThePanelOnly) {
    Screen screen;
    ui::ImGuiLayer layer;
    const workflow::Status st = status(State::Seeding);
    layer.feed(pointer(platform::InputEvent::Kind::PointerMove,
                       {layout_.panel.x + 20.0, layout_.panel.y + 300.0}));
    frame(layer, st);
    frame(layer, st);
    EXPECT_TRUE(layer.wantsPointer());
    layer.feed(pointer(platform::InputEvent::Kind::PointerMove, {100.0, 100.0}));
    frame(layer, st);
    EXPECT_FALSE(layer.wantsPointer());
    // A touch on a view emits nothing from the panel.
    layer.feed(pointer(platform::InputEvent::Kind::PointerDown, {100.0, 100.0}));
    layer.feed(pointer(platform::InputEvent::Kind::PointerUp, {100.0, 100.0}));
    EXPECT_TRUE(frame(layer, st).empty());
    EXPECT_TRUE(frame(layer, st).empty());
}

TEST_F(UiPanel, RestoresTheGlStateItChanges) {
    Screen screen;
    ui::ImGuiLayer layer;
    gpu::Texture foreign = gpu::createTexture();
    glActiveTexture(GL_TEXTURE1);
    glBindTexture(GL_TEXTURE_2D, foreign.id());
    glActiveTexture(GL_TEXTURE0);
    glBindTexture(GL_TEXTURE_2D, foreign.id());
    glDisable(GL_BLEND);
    glEnable(GL_DEPTH_TEST);
    glViewport(10, 20, 300, 200);
    glDisable(GL_SCISSOR_TEST);
    GLint fbBefore = 0;
    glGetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &fbBefore);
    frame(layer, status(State::Evolving));
    GLint texture = 0;
    glGetIntegerv(GL_TEXTURE_BINDING_2D, &texture);
    EXPECT_EQ(static_cast<GLuint>(texture), foreign.id());
    GLint active = 0;
    glGetIntegerv(GL_ACTIVE_TEXTURE, &active);
    EXPECT_EQ(active, GL_TEXTURE0);
    EXPECT_FALSE(glIsEnabled(GL_BLEND));
    EXPECT_TRUE(glIsEnabled(GL_DEPTH_TEST));
    EXPECT_FALSE(glIsEnabled(GL_SCISSOR_TEST));
    std::array<GLint, 4> viewport{};
    glGetIntegerv(GL_VIEWPORT, viewport.data());
    EXPECT_EQ(viewport, (std::array<GLint, 4>{10, 20, 300, 200}));
    GLint fbAfter = 0;
    glGetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &fbAfter);
    EXPECT_EQ(fbAfter, fbBefore);
    GLint program = 0;
    glGetIntegerv(GL_CURRENT_PROGRAM, &program);
    EXPECT_EQ(program, 0);
    glDisable(GL_DEPTH_TEST);
    glEnable(GL_BLEND);
    glViewport(0, 0, kW, kH);
    EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
}

TEST_F(UiPanel, FallsBackToTheBuiltInFontAndDrawsCaptions) {
    Screen screen;
    ui::ImGuiLayerOptions options;
    options.fontPath = "/nonexistent/steerseg-font.ttf";
    ui::ImGuiLayer layer(options);
    EXPECT_TRUE(layer.fallbackFont());
    options.fontPath = std::string(STEERSEG_UI_TEST_SOURCE); // a file, but not a font
    EXPECT_TRUE(ui::ImGuiLayer(options).fallbackFont());
    const workflow::Status st = status(State::Inspect);
    ui::ScreenState s;
    s.layout = layout_;
    Geometry g;
    g.dims = st.scan.dims;
    render::ViewParams p;
    p.kind = render::ViewKind::Axial;
    p.size = {layout_.slice1.w, layout_.slice1.h};
    s.slice1 = ui::SliceView{render::sliceFrame(g, p), p.size, layout_.slice1};
    frame(layer, st, &s);
    Screen::clear();
    frame(layer, st, &s);
    const std::vector<std::uint8_t> px = screen.read();
    EXPECT_GT(count(px, layout_.panel).changed, layout_.panel.w * layout_.panel.h / 2);
    const auto corner = [](const ui::Rect& r) { return ui::Rect{r.x, r.y, 120, 40}; };
    EXPECT_GT(count(px, corner(layout_.view3d)).white, 10) << "the 3D view's caption";
    EXPECT_GT(count(px, corner(layout_.slice1)).white, 10) << "the contour view's caption";
    EXPECT_EQ(count(px, corner(layout_.slice2)).changed, 0) << "no speed view given, no caption";
}

// The whole touch UI: a tap on a slice seeds at the voxel under the finger, a tap on the panel
// is the panel's alone, and a finger held on a slice erases once its long press is due.
TEST_F(UiPanel, TouchUiRoutesTapsToViewsAndPanel) {
    Screen screen;
    ui::TouchUiOptions options;
    options.scans = kScans;
    ui::TouchUi touch(options);
    workflow::Status st = status(State::Seeding);
    ui::ScreenState s;
    s.layout = layout_;
    Geometry g;
    g.dims = st.scan.dims;
    for (auto [kind, rect, view] :
         {std::tuple{render::ViewKind::Axial, layout_.slice1, &s.slice1},
          std::tuple{render::ViewKind::Coronal, layout_.slice2, &s.slice2}}) {
        render::ViewParams p;
        p.kind = kind;
        p.size = {rect.w / 2, rect.h / 2};
        *view = ui::SliceView{render::sliceFrame(g, p), p.size, rect};
    }
    double t = 0.0;
    std::vector<Action> out;
    const auto frames = [&](int n) {
        for (int i = 0; i < n; ++i) {
            t += 1.0 / 30.0;
            for (const Action& a : touch.drawFrame({kW, kH}, t, s, st)) {
                out.push_back(a);
            }
        }
    };
    const auto at = [&](platform::InputEvent::Kind kind, glm::dvec2 p) {
        platform::InputEvent e = pointer(kind, p);
        e.time = t;
        touch.feed(e, s, st, out);
    };
    frames(2);
    ASSERT_TRUE(out.empty());

    const glm::dvec2 onSlice(layout_.slice1.x + 0.5 * layout_.slice1.w,
                             layout_.slice1.y + 0.5 * layout_.slice1.h);
    at(platform::InputEvent::Kind::PointerDown, onSlice);
    at(platform::InputEvent::Kind::PointerUp, onSlice);
    frames(2);
    ASSERT_EQ(out.size(), 1U);
    const auto* seed = std::get_if<model::AddSeed>(&out[0]);
    ASSERT_NE(seed, nullptr);
    EXPECT_NEAR(glm::length(seed->voxel - *ui::voxelAtScreen(*s.slice1, onSlice)), 0.0, 1e-9);
    out.clear();

    const std::optional<ui::Rect> run = touch.panel().widgetRect("Run");
    ASSERT_TRUE(run);
    const glm::dvec2 onRun(run->x + 0.5 * run->w, run->y + 0.5 * run->h);
    at(platform::InputEvent::Kind::PointerDown, onRun);
    at(platform::InputEvent::Kind::PointerUp, onRun);
    frames(3);
    ASSERT_EQ(out.size(), 1U);
    EXPECT_TRUE(std::holds_alternative<model::Run>(out[0]));
    out.clear();

    st.state = State::Evolving;
    const glm::dvec2 onSpeed(layout_.slice2.x + 0.5 * layout_.slice2.w,
                             layout_.slice2.y + 0.5 * layout_.slice2.h);
    at(platform::InputEvent::Kind::PointerDown, onSpeed);
    frames(30); // a second: the long press is due while the finger is still down
    ASSERT_EQ(out.size(), 1U);
    EXPECT_TRUE(std::holds_alternative<model::Erase>(out[0]));
    at(platform::InputEvent::Kind::PointerUp, onSpeed);
    frames(2);
    EXPECT_EQ(out.size(), 1U) << "nothing more when the finger lifts";
}

// The resume offer over the panel: its buttons answer it, and a tap on it is no panel action.
TEST_F(UiPanel, PromptOverThePanelIsAnsweredByItsButtons) {
    Screen screen;
    ui::TouchUiOptions options;
    options.scans = kScans;
    ui::TouchUi touch(options);
    const workflow::Status st = status(State::NoScan);
    ui::ScreenState s;
    s.layout = layout_;
    double t = 0.0;
    std::vector<Action> out;
    const auto frames = [&](int n) {
        for (int i = 0; i < n; ++i) {
            t += 1.0 / 30.0;
            for (const Action& a : touch.drawFrame({kW, kH}, t, s, st)) {
                out.push_back(a);
            }
        }
    };
    touch.setPrompt(
        ui::Prompt{"Resume the last session?", "ball, evolving", {"Resume", "Discard"}});
    frames(2);
    ASSERT_EQ(touch.promptButtons().size(), 2U);
    for (const ui::Rect& r : touch.promptButtons()) {
        EXPECT_TRUE(layout_.panel.contains(r.x, r.y)) << "drawn over the panel";
        EXPECT_GE(r.h, static_cast<int>(touch.layer().touchPx()) - 1) << "a full touch target";
    }
    EXPECT_FALSE(touch.takePromptChoice());
    const ui::Rect discard = touch.promptButtons()[1];
    const glm::dvec2 on(discard.x + 0.5 * discard.w, discard.y + 0.5 * discard.h);
    for (const auto kind :
         {platform::InputEvent::Kind::PointerDown, platform::InputEvent::Kind::PointerUp}) {
        platform::InputEvent e = pointer(kind, on);
        e.time = t;
        touch.feed(e, s, st, out);
        frames(1);
    }
    frames(1);
    EXPECT_EQ(touch.takePromptChoice(), std::optional<std::size_t>(1));
    EXPECT_FALSE(touch.takePromptChoice()) << "answered once";
    EXPECT_TRUE(out.empty()) << "the panel under the prompt did not act";
    touch.setPrompt(std::nullopt);
    frames(1);
    EXPECT_TRUE(touch.promptButtons().empty());
}

// On a portrait screen the panel is a wide strip below the views: the whole Paused panel
// (the state with the most controls) fits without scrolling.
TEST_F(UiPanel, PortraitPanelFitsItsControls) {
    Screen screen;
    ui::ImGuiLayer layer;
    layout_ = ui::computeLayout(800, 1280, 96.0);
    // The offscreen target is 1280 x 800: draw the 800-wide portrait panel into its top left.
    layout_.panel.y = 0;
    workflow::Status st = status(State::Paused);
    frame(layer, st);
    frame(layer, st);
    const ui::Rect panel = layout_.panel;
    for (const char* label :
         {"Run", "+##radius", "Review##proceed", "Sagittal##view2", "CT bone##preset"}) {
        const auto r = panel_.widgetRect(label);
        ASSERT_TRUE(r) << label;
        EXPECT_GE(r->x, panel.x) << label;
        EXPECT_LE(r->x + r->w, panel.x + panel.w) << label;
        EXPECT_GE(r->y, panel.y) << label;
        EXPECT_LE(r->y + r->h, panel.y + panel.h) << label << " is below the panel";
    }
    if (const char* dir = std::getenv("STEERSEG_UI_SNAPSHOTS")) {
        Screen::clear();
        frame(layer, st);
        exports::writeImage(std::filesystem::path(dir) / "panel_portrait.png",
                            RgbaImage{kW, kH, screen.read()});
    }
}

// At a high DPI the landscape panel is taller than the screen: a finger dragging its
// background scrolls it (ImGui 1.86 scrolls only with the wheel), and a tap still works after.
TEST_F(UiPanel, FingerDragScrollsATallPanel) {
    Screen screen;
    ui::ImGuiLayerOptions options;
    options.dpi = 200.0;
    ui::ImGuiLayer layer(options);
    layout_ = ui::computeLayout(kW, kH, options.dpi);
    const workflow::Status st = status(State::Evolving);
    frame(layer, st);
    frame(layer, st);
    const auto before = panel_.widgetRect("Sagittal##view2");
    ASSERT_TRUE(before);
    ASSERT_GT(before->y + before->h, kH) << "the test needs a panel taller than the screen";
    for (const auto& [label, r] : panel_.widgetRects()) {
        EXPECT_GE(r.x, layout_.panel.x) << label;
        EXPECT_LE(r.x + r.w, layout_.panel.x + layout_.panel.w) << label;
        EXPECT_GE(r.w + 1, static_cast<int>(layer.touchPx())) << label;
    }
    // The hint's text is no widget: start there and drag up 1200 px in steps (ImGui stops the
    // scroll at the content's end).
    const auto seed = panel_.widgetRect("Review##proceed");
    ASSERT_TRUE(seed);
    glm::dvec2 at(layout_.panel.x + 0.5 * layout_.panel.w, seed->y - 8.0);
    layer.feed(pointer(platform::InputEvent::Kind::PointerDown, at));
    frame(layer, st);
    for (int i = 0; i < 40; ++i) {
        at.y -= 30.0;
        layer.feed(pointer(platform::InputEvent::Kind::PointerMove, at));
        EXPECT_TRUE(frame(layer, st).empty());
    }
    layer.feed(pointer(platform::InputEvent::Kind::PointerUp, at));
    EXPECT_TRUE(frame(layer, st).empty());
    frame(layer, st);
    const auto after = panel_.widgetRect("Sagittal##view2");
    ASSERT_TRUE(after);
    EXPECT_LT(after->y, before->y - 100) << "scrolled up";
    EXPECT_LE(after->y + after->h, kH) << "the last row is on the screen now";
    const std::vector<Action> tapped = tap(layer, st, "Sagittal##view2");
    ASSERT_EQ(tapped.size(), 1U);
    EXPECT_EQ(std::get<model::ShowSlices>(tapped[0]).second, model::SliceAxis::Sagittal);
}

// ImGui takes one press or release a frame, and the kiosk draws a frame only when something
// asks for one: a tap's down and up that came together keep the UI asking until the panel has
// taken both, or the release (and the button's action) would wait for an unrelated redraw.
TEST_F(UiPanel, TheTouchUiAsksForFramesUntilThePanelHasTakenATap) {
    Screen screen;
    ui::TouchUi touch(ui::TouchUiOptions{});
    const workflow::Status st = status(State::Seeding);
    ui::ScreenState s;
    s.layout = layout_;
    double t = 0.0;
    std::vector<Action> out;
    const auto frame1 = [&] {
        t += 1.0 / 30.0;
        for (const Action& a : touch.drawFrame({kW, kH}, t, s, st)) {
            out.push_back(a);
        }
    };
    frame1();
    frame1();
    EXPECT_FALSE(touch.pressing());
    const std::optional<ui::Rect> run = touch.panel().widgetRect("Run");
    ASSERT_TRUE(run);
    const glm::dvec2 at(run->x + 0.5 * run->w, run->y + 0.5 * run->h);
    for (const auto kind :
         {platform::InputEvent::Kind::PointerDown, platform::InputEvent::Kind::PointerUp}) {
        platform::InputEvent e = pointer(kind, at);
        e.time = t;
        touch.feed(e, s, st, out);
    }
    EXPECT_TRUE(touch.pressing()) << "the finger is up, but the panel has not seen the tap";
    frame1(); // the press
    EXPECT_TRUE(touch.pressing()) << "the release is still to come";
    frame1(); // the release: Run
    EXPECT_FALSE(touch.pressing());
    ASSERT_EQ(out.size(), 1U);
    EXPECT_TRUE(std::holds_alternative<model::Run>(out[0]));
}

// Issue 49: a structure renamed and recoloured by touch alone, through the whole touch UI and
// the workflow on the in-memory engine, its actions handled between frames as the kiosk does.
// Rename opens the keyboard across the screen's bottom with the name; a name the workflow
// refuses keeps it open with the reason; the views take no gesture while it is open; OK with a
// good name renames and closes it; a swatch recolours.
TEST_F(UiPanel, ARenameAndARecolourByTouchAlone) {
    Screen screen;
    ui::TouchUi touch(ui::TouchUiOptions{});
    Rig rig;
    rig.driveTo(State::Paused);
    using model::StructureOp;
    ASSERT_TRUE(rig.act(model::EditStructure{StructureOp::Add, "Spleen", {}, {}}).accepted);
    ASSERT_TRUE(rig.act(model::EditStructure{StructureOp::Select, "Segment 1", {}, {}}).accepted);
    ASSERT_TRUE(rig.act(model::Finish{}).accepted);
    ASSERT_EQ(rig.state(), State::Review);

    ui::ScreenState s;
    s.layout = layout_;
    Geometry g;
    g.dims = rig.status().scan.dims;
    render::ViewParams p;
    p.kind = render::ViewKind::Axial;
    p.size = {layout_.slice1.w, layout_.slice1.h};
    s.slice1 = ui::SliceView{render::sliceFrame(g, p), p.size, layout_.slice1};

    double t = 0.0;
    std::vector<Action> sent; // every action of the touches, as handed to the workflow
    std::vector<std::string> refusals;
    const auto handle = [&](std::vector<Action> actions) {
        for (const Action& a : actions) {
            sent.push_back(a);
            const workflow::Workflow::Outcome o = rig.act(a);
            if (!o.accepted) {
                refusals.push_back(o.reason);
            }
        }
    };
    const auto frames = [&](int n) {
        for (int i = 0; i < n; ++i) {
            t += 1.0 / 30.0;
            handle(touch.drawFrame({kW, kH}, t, s, rig.status()));
        }
    };
    const auto touchAt = [&](platform::InputEvent::Kind kind, glm::dvec2 at) {
        platform::InputEvent e = pointer(kind, at);
        e.time = t;
        std::vector<Action> out;
        touch.feed(e, s, rig.status(), out);
        handle(out);
    };
    const auto tapAt = [&](const ui::Rect& r) {
        const glm::dvec2 at(r.x + 0.5 * r.w, r.y + 0.5 * r.h);
        touchAt(platform::InputEvent::Kind::PointerDown, at);
        touchAt(platform::InputEvent::Kind::PointerUp, at);
        frames(4); // ImGui takes the press and the release a frame each; then what it opened
    };
    const auto tapWidget = [&](const std::string& label) {
        const std::optional<ui::Rect> r = touch.panel().widgetRect(label);
        ASSERT_TRUE(r) << label;
        ASSERT_LE(r->y + r->h, kH) << label << " is on the screen";
        tapAt(*r);
    };
    const auto typeKeys = [&](std::initializer_list<const char*> names) {
        for (const char* name : names) {
            const auto& keys = touch.panel().keyboardFrame().keys;
            const auto it = keys.find(name);
            ASSERT_NE(it, keys.end()) << name;
            tapAt(it->second);
        }
    };
    // A finger dragged up a slice view, above the keyboard: paging, when the views take it.
    const auto dragOnSlice = [&] {
        glm::dvec2 at(layout_.slice1.x + 0.5 * layout_.slice1.w, layout_.slice1.y + 150.0);
        touchAt(platform::InputEvent::Kind::PointerDown, at);
        for (int i = 0; i < 6; ++i) {
            at.y -= 20.0;
            touchAt(platform::InputEvent::Kind::PointerMove, at);
        }
        touchAt(platform::InputEvent::Kind::PointerUp, at);
        frames(1);
    };
    const auto paged = [&] {
        return std::count_if(sent.begin(), sent.end(), [](const Action& a) {
            return std::holds_alternative<model::PageSlice>(a);
        });
    };

    frames(2);
    ASSERT_TRUE(sent.empty());
    tapWidget("Rename##structure");
    ASSERT_TRUE(touch.panel().keyboardOpen());
    EXPECT_TRUE(sent.empty()) << "Rename only opens the keyboard";
    const ui::KeyboardFrame& kb = touch.panel().keyboardFrame();
    EXPECT_EQ(kb.window.x, 0);
    EXPECT_EQ(kb.window.w, kW) << "across the screen";
    EXPECT_NEAR(kb.window.y + kb.window.h, kH, 1) << "at its bottom";
    EXPECT_LT(kb.window.h, kH / 2);
    for (const auto& [name, r] : kb.keys) {
        EXPECT_GE(r.w + 1, static_cast<int>(touch.layer().touchPx())) << name;
        EXPECT_GE(r.h + 1, static_cast<int>(touch.layer().touchPx())) << name;
        EXPECT_GE(r.y, kb.window.y) << name;
        EXPECT_LE(r.y + r.h, kb.window.y + kb.window.h) << name << " is on the keyboard";
    }
    EXPECT_EQ(touch.panel().editing().keyboard()->text(), "Segment 1");

    dragOnSlice();
    EXPECT_EQ(paged(), 0) << "the views take no gesture while the keyboard is open";

    // The other structure's name: the workflow refuses, the keyboard stays with the reason.
    typeKeys({"clear", "shift", "s", "p", "l", "e", "e", "n", "ok"});
    ASSERT_EQ(refusals.size(), 1U);
    EXPECT_NE(refusals[0].find("exists already"), std::string::npos) << refusals[0];
    EXPECT_TRUE(touch.panel().keyboardOpen());
    EXPECT_EQ(touch.panel().editing().problem(), refusals[0]);
    if (const char* dir = std::getenv("STEERSEG_UI_SNAPSHOTS")) {
        Screen::clear();
        frames(1);
        exports::writeImage(std::filesystem::path(dir) / "panel_keyboard.png",
                            RgbaImage{kW, kH, screen.read()});
    }

    typeKeys({"clear", "shift", "t", "u", "m", "o", "u", "r", "space", "2", "ok"});
    EXPECT_EQ(refusals.size(), 1U);
    EXPECT_FALSE(touch.panel().keyboardOpen()) << "taken: the keyboard closes";
    ASSERT_EQ(rig.status().structures.size(), 2U);
    EXPECT_EQ(rig.status().structures[0].info.name, "Tumour 2");
    const auto renames = std::count_if(sent.begin(), sent.end(), [](const Action& a) {
        const auto* e = std::get_if<model::EditStructure>(&a);
        return e != nullptr && e->op == StructureOp::Rename && e->name == "Segment 1";
    });
    EXPECT_EQ(renames, 2);

    dragOnSlice();
    EXPECT_GT(paged(), 0) << "the views take gestures again";

    tapWidget("Colour##structure");
    if (const char* dir = std::getenv("STEERSEG_UI_SNAPSHOTS")) {
        Screen::clear();
        frames(1);
        exports::writeImage(std::filesystem::path(dir) / "panel_swatches.png",
                            RgbaImage{kW, kH, screen.read()});
    }
    tapWidget("##colour5");
    EXPECT_EQ(rig.status().structures[0].info.colour, model::paletteColour(5));
    frames(1);
    EXPECT_FALSE(touch.panel().widgetRect("##colour5")) << "a tap picks and closes the swatches";
    EXPECT_EQ(refusals.size(), 1U);
}

// The PACS section by touch alone: a peer's button chooses it (the form's, no action), Search
// asks it, a study's Series lists its series on the peer it was found on, and a series' own
// Retrieve names that series.
TEST_F(UiPanel, APeerTappedThenSearchSeriesAndOneSeriesRetrieved) {
    Screen screen;
    ui::ImGuiLayer layer;
    workflow::Status st = status(State::NoScan);
    st.pacs.peers = {"pacs", "archive"};
    st.pacs.fields = {"patient_id"};
    st.pacs.studies = {{"1.2.3", "2024-01-05  DOE JANE"}};
    st.pacs.studiesPeer = "archive";
    EXPECT_TRUE(tap(layer, st, "archive##pacs_peer_archive").empty());
    EXPECT_EQ(panel_.pacsForm().peer(), "archive");
    const std::vector<Action> search = tap(layer, st, "Search##pacs_search");
    ASSERT_EQ(search.size(), 1U);
    EXPECT_EQ(std::get<model::SearchPacs>(search[0]).peer, "archive");

    const std::vector<Action> list = tap(layer, st, "Series##pacs_series_of0");
    ASSERT_EQ(list.size(), 1U);
    EXPECT_EQ(std::get<model::ListPacsSeries>(list[0]).studyUid, "1.2.3");
    EXPECT_EQ(std::get<model::ListPacsSeries>(list[0]).peer, "archive");

    st.pacs.seriesStudyUid = "1.2.3";
    st.pacs.seriesPeer = "archive";
    st.pacs.seriesLine = "1 series of the study on archive";
    st.pacs.series = {{"1.2.3.1", "CT", "2", "Chest", 60}};
    const std::vector<Action> one =
        tap(layer, st, "Retrieve CT  #2  Chest  (60 images)##pacs_series0");
    ASSERT_EQ(one.size(), 1U);
    const auto& retrieve = std::get<model::RetrievePacs>(one[0]);
    EXPECT_EQ(retrieve.studyUid, "1.2.3");
    EXPECT_EQ(retrieve.seriesUid, "1.2.3.1");
    EXPECT_EQ(retrieve.peer, "archive");
    // The series row lies under its study's row, inside the panel.
    const auto study = panel_.widgetRect("Retrieve 2024-01-05  DOE JANE##pacs_study0");
    const auto row = panel_.widgetRect("Retrieve CT  #2  Chest  (60 images)##pacs_series0");
    ASSERT_TRUE(study && row);
    EXPECT_GT(row->y, study->y);
    EXPECT_LE(row->y + row->h, layout_.panel.y + layout_.panel.h);
}

} // namespace steerseg::test
