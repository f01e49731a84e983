#include "ui/touch_ui.hpp"

#include "ui/overlays.hpp"

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
        for (model::Action& a : interaction_.onGesture(g, screen, status)) {
            out.push_back(std::move(a));
        }
    }
}

std::vector<model::Action> TouchUi::drawFrame(const glm::ivec2& screenSize, double time,
                                              const ScreenState& screen,
                                              const workflow::Status& status) {
    std::vector<model::Action> out;
    for (const Gesture& g : gestures_.update(time)) {
        for (model::Action& a : interaction_.onGesture(g, screen, status)) {
            out.push_back(std::move(a));
        }
    }
    layer_.beginFrame(screenSize, time);
    for (model::Action& a : panel_.draw(layer_, status, screen.layout.panel, scans_)) {
        out.push_back(std::move(a));
    }
    drawViewCaptions(layer_, screen, status);
    drawBoxes(layer_, screen, status, interaction_.boxDraft());
    if (const std::optional<model::StrokeMode> mode = interaction_.strokeMode()) {
        drawStrokePath(layer_, interaction_.strokePath(), *mode);
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
