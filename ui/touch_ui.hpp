#pragma once

// The kiosk's whole touch UI in one object: pointer events go both to ImGui (the panel) and to
// the gesture recognizer (the views); each frame draws the panel and the captions and returns
// the actions of both. The kiosk's frame loop:
//   for (event : events) ui.feed(rotation.toLogical(event), screen, status, actions);
//   <render the views into screen's rects>
//   append(actions, ui.drawFrame(logicalSize, now, screen, status));
// While the panel's on-screen keyboard is open (renaming a structure) it lies across the bottom
// of the screen and the views take no gestures.
#include "ui/gestures.hpp"
#include "ui/imgui_layer.hpp"
#include "ui/interaction.hpp"
#include "ui/panel.hpp"
#include "ui/prompt.hpp"
#include "ui/screen_state.hpp"
#include "ui/structure_contours.hpp"

#include <cstddef>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace steerseg::ui {

struct TouchUiOptions {
    double dpi = 96.0;
    double touchMm = 9.0;   // config ui.touch_target_mm
    double fontScale = 1.0; // config ui.font_scale
    double probeRadiusMm = 5.0;
    double longPressMs = 600.0;
    std::string fontPath;           // "" = DejaVuSans
    std::vector<std::string> scans; // the Load list: "builtin:sample" and paths
};

class TouchUi {
  public:
    // Needs a current GLES 3 context (see ImGuiLayer).
    explicit TouchUi(const TouchUiOptions& options);

    // One event in logical pixels: the view gestures it completes append their actions.
    void feed(const platform::InputEvent& event, const ScreenState& screen,
              const workflow::Status& status, std::vector<model::Action>& out);
    // Long presses due by `time`, the panel and the captions, drawn into the bound framebuffer.
    std::vector<model::Action> drawFrame(const glm::ivec2& screenSize, double time,
                                         const ScreenState& screen, const workflow::Status& status);

    void setScans(std::vector<std::string> scans) { scans_ = std::move(scans); }
    // A question over the panel until it is cleared (nullopt); the button pressed since the
    // last call, once.
    void setPrompt(std::optional<Prompt> prompt) { prompt_ = std::move(prompt); }
    std::optional<std::size_t> takePromptChoice() { return std::exchange(promptChoice_, {}); }
    // Where the prompt's buttons were drawn last frame (empty: no prompt).
    [[nodiscard]] const std::vector<Rect>& promptButtons() const { return promptButtons_; }
    [[nodiscard]] const ImGuiLayer& layer() const { return layer_; }
    [[nodiscard]] const Panel& panel() const { return panel_; }
    // A finger or button is down (a long press may come due without a new event), or the
    // panel has a press or release still to take (one a frame: a tap's down and up that came
    // in one frame, a run of taps on the keyboard): the next frame must be drawn.
    [[nodiscard]] bool pressing() const {
        return gestures_.pointersDown() > 0 || layer_.eventsPending();
    }

  private:
    [[nodiscard]] bool viewsTakeGestures() const;

    ImGuiLayer layer_;
    GestureRecognizer gestures_;
    Interaction interaction_;
    Panel panel_;
    StructureContours contours_;
    std::vector<std::string> scans_;
    std::optional<Prompt> prompt_;
    std::optional<std::size_t> promptChoice_;
    std::vector<Rect> promptButtons_;
};

} // namespace steerseg::ui
