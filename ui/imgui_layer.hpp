#pragma once

// Dear ImGui for the kiosk: the context, the GLES 3 renderer backend and the font, fed with
// the screen's pointer events. One per GL context, used on that context's thread.
//   layer.feed(event) ...; layer.beginFrame(size, time); <panel and overlays>; layer.endFrame();
#include "platform/input_event.hpp"

#include <cstddef>
#include <deque>
#include <glm/glm.hpp>
#include <string>
#include <vector>

struct ImGuiContext;
struct ImFont;

namespace steerseg::ui {

// fonts-dejavu-core's DejaVuSans: the panel's font where options name none.
inline constexpr const char* kDefaultFontPath = "/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf";

struct ImGuiLayerOptions {
    double dpi = 96.0;
    double touchMm = 9.0;   // the smallest touch target (config ui.touch_target_mm, >= 9)
    double fontScale = 1.0; // text relative to the size the touch target implies
    std::string fontPath;   // "" = DejaVuSans of fonts-dejavu-core
};

class ImGuiLayer {
  public:
    // Needs a current GLES 3 context. Throws std::runtime_error when the backend cannot start.
    // A missing or unreadable font file falls back to ImGui's built-in font at the same size
    // (said once on stderr).
    explicit ImGuiLayer(const ImGuiLayerOptions& options = {});
    ~ImGuiLayer();
    ImGuiLayer(const ImGuiLayer&) = delete;
    ImGuiLayer& operator=(const ImGuiLayer&) = delete;

    // Pointer events in logical pixels. Only the first finger down (or the mouse) drives
    // ImGui. A press and its release that arrive within one frame are spread over two, as
    // ImGui 1.86 reads the button's state once a frame and would miss the tap.
    void feed(const platform::InputEvent& event);

    void beginFrame(const glm::ivec2& screenSize, double time);
    // Draws into the framebuffer bound now (viewport: the screen size), inside a
    // gpu::GlStateGuard; the backend restores the blend, scissor and vertex state it changes.
    void endFrame();

    // Whether ImGui has the pointer (over the panel, or holding one of its widgets): gestures
    // that start then are the panel's, not the views'.
    [[nodiscard]] bool wantsPointer() const;
    // Presses or releases fed that ImGui has yet to see (it takes one a frame).
    [[nodiscard]] bool eventsPending() const { return !pending_.empty(); }

    [[nodiscard]] double touchPx() const { return touchPx_; }
    [[nodiscard]] double fontPx() const { return fontPx_; }
    [[nodiscard]] bool fallbackFont() const { return fallbackFont_; }
    [[nodiscard]] ImFont* largeFont() const { return largeFont_; }
    [[nodiscard]] ImGuiContext* context() const { return context_; }

  private:
    void loadFonts(const std::string& path);
    void applyPointer();

    ImGuiContext* context_ = nullptr;
    bool backend_ = false;
    double touchPx_ = 34.0;
    double fontPx_ = 17.0;
    bool fallbackFont_ = false;
    ImFont* largeFont_ = nullptr;
    std::vector<unsigned char> fontData_; // the atlas reads it while (re)building
    std::deque<platform::InputEvent> pending_;
    int driver_ = -1; // the pointer slot ImGui follows, while it is down
    double lastTime_ = -1.0;
    bool inFrame_ = false;
};

} // namespace steerseg::ui
