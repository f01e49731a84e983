#pragma once

// The logical screen, as the operator sees it upright: the views' pictures blitted into their
// rectangles, the UI drawn on top, then the whole turned by the panel's mounting onto the
// display's framebuffer. Frames saved to files are the logical screen, so a scripted session
// draws the same PNGs on every backend and rotation.
#include "core/rgba_image.hpp"
#include "gpu/gl_handle.hpp"
#include "render/render_target.hpp"
#include "ui/layout.hpp"

#include <glm/glm.hpp>

namespace steerseg::kiosk {

// The logical size of a display of `physical` pixels mounted at `rotationDeg` (0, 90, 180, 270).
glm::ivec2 logicalSize(const glm::ivec2& physical, int rotationDeg);

class ScreenCompositor {
  public:
    ScreenCompositor(const glm::ivec2& physicalSize, int rotationDeg);

    [[nodiscard]] glm::ivec2 size() const { return size_; }
    // The logical screen's framebuffer, bound and cleared to the background.
    void begin(const glm::vec3& background);
    [[nodiscard]] unsigned int framebuffer() const { return screen_.framebuffer(); }
    // A picture (row 0 at the top, as the renderer writes it) scaled into `rect`.
    void drawPicture(unsigned int texture, const glm::ivec2& pictureSize, const ui::Rect& rect);
    // The logical screen onto the display's framebuffer, turned as mounted.
    void present(unsigned int displayFramebuffer, const glm::ivec2& displaySize);
    // The logical screen as it is now (row 0 at the top).
    [[nodiscard]] RgbaImage capture() const;

  private:
    glm::ivec2 size_;
    int quarterTurns_;
    render::RenderTarget screen_; // GL rows: the bottom of the screen first
    gpu::Framebuffer source_;     // a picture attached for blitting
    gpu::Program present_;
    gpu::VertexArray vertexArray_;
};

} // namespace steerseg::kiosk
