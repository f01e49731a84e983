#include "ui/touch_ui.hpp"

#include "ui/overlays.hpp"

#include <imgui.h>

namespace steerseg::ui {

namespace {

ImGuiLayerOptions layerOptions(const TouchUiOptions& o) {
    ImGuiLayerOptions l;
    l.dpi = o.dpi;
    l.touchMm = o.touchMm;
    l.fontScale = o.fontScale;
    l.fontPath = o.fontPath;
    return l;
}

} // namespace

TouchUi::TouchUi(const TouchUiOptions& options)
    : layer_(layerOptions(options)),
      gestures_(gestureConfig(options.dpi, 2.0, options.longPressMs)),
      interaction_(interactionConfig(options.dpi, options.probeRadiusMm)), scans_(options.scans) {}

void TouchUi::feed(const platform::InputEvent& event, const ScreenState& screen,
                   const workflow::Status& status, std::vector<model::Action>& out) {
    layer_.feed(event);
    // Gestures that begin on the panel are ImGui's: Interaction ignores the panel's region.
    for (const Gesture& g : gestures_.feed(event)) {
        if (viewsTakeGestures()) {
            for (model::Action& a : interaction_.onGesture(g, screen, status)) {
                out.push_back(std::move(a));
            }
        }
    }
}

bool TouchUi::viewsTakeGestures() const {
    // The keyboard lies over the views: a finger typing on it must not seed or erase there.
    return !panel_.keyboardOpen();
}

std::vector<model::Action> TouchUi::drawFrame(const glm::ivec2& screenSize, double time,
                                              const ScreenState& screen,
                                              const workflow::Status& status) {
    std::vector<model::Action> out;
    for (const Gesture& g : gestures_.update(time)) {
        if (viewsTakeGestures()) {
            for (model::Action& a : interaction_.onGesture(g, screen, status)) {
                out.push_back(std::move(a));
            }
        }
    }
    layer_.beginFrame(screenSize, time);
    for (model::Action& a : panel_.draw(layer_, status, screen.layout.panel, scans_)) {
        out.push_back(std::move(a));
    }
    for (model::Action& a : panel_.drawKeyboard(layer_, {0, 0, screenSize.x, screenSize.y})) {
        out.push_back(std::move(a));
    }
    // The views' overlays go on ImGui's foreground, above every window: kept above the
    // keyboard's top edge while it is open.
    ImDrawList* overlays = ImGui::GetForegroundDrawList();
    const Rect& keyboard = panel_.keyboardFrame().window;
    const bool clip = panel_.keyboardOpen() && !keyboard.empty();
    if (clip) {
        overlays->PushClipRect(
            ImVec2(0.0F, 0.0F),
            ImVec2(static_cast<float>(screenSize.x), static_cast<float>(keyboard.y)), true);
    }
    drawViewCaptions(layer_, screen, status);
    contours_.draw(layer_, screen, status.scan.dims);
    drawMeasuredDiameters(layer_, screen, status);
    drawBoxes(layer_, screen, status, interaction_.boxDraft());
    if (const std::optional<model::StrokeMode> mode = interaction_.strokeMode()) {
        drawStrokePath(layer_, interaction_.strokePath(), *mode);
    }
    if (clip) {
        overlays->PopClipRect();
    }
    promptButtons_.clear();
    if (prompt_) {
        PromptFrame drawn = drawPrompt(layer_, *prompt_, screen.layout.panel);
        if (drawn.chosen) {
            promptChoice_ = drawn.chosen;
        }
        promptButtons_ = std::move(drawn.buttons);
    }
    layer_.endFrame();
    return out;
}

} // namespace steerseg::ui
