#pragma once

#include <glm/glm.hpp>

namespace steerseg::kiosk {

// One view's picture on a machine that may be too slow to draw it whole within a frame
// (llvmpipe draws a 1280x800 3D view in tens of seconds). While what the view shows changes
// (camera, surface, parameters), each frame draws a preview whose resolution is chosen so the
// draw fits the time it is given; once still, the full-resolution picture is drawn in tiles
// (whole bands of rows where they fit, parts of an 8-row strip where not) over as many frames
// as it takes, and shown when complete. The cost per pixel is learned from every draw. On a
// GPU the preview is full size and the refinement never starts.
class ViewRefiner {
  public:
    struct Plan {
        enum Kind { Nothing, Preview, Tile } kind = Nothing;
        glm::ivec2 size{0};              // the picture to draw
        glm::ivec4 region{0, 0, -1, -1}; // Tile: x, y, width, height (render::ViewParams::region)
    };

    // maxPreviewScale: the largest preview relative to the full picture (config
    // frame.interactive_scale); 1 lets a fast machine draw full previews. A preview keeps at
    // least minPreviewPixels pixels, however slow the machine.
    explicit ViewRefiner(double maxPreviewScale = 1.0, double minPreviewPixels = 256.0);

    void changed();
    [[nodiscard]] Plan plan(const glm::ivec2& fullSize, double seconds);
    void drawn(const Plan& plan, double seconds);

    // The full-resolution picture is complete and shows the current state.
    [[nodiscard]] bool fullReady() const { return fullReady_; }
    // Something has been drawn since the last change (a preview or the full picture).
    [[nodiscard]] bool anyReady() const { return previewReady_ || fullReady_; }
    // A change waits for its preview.
    [[nodiscard]] bool dirty() const { return dirty_; }
    [[nodiscard]] double secondsPerPixel() const { return secondsPerPixel_; }

  private:
    double maxScale_;
    double minPixels_;
    double secondsPerPixel_ = 0.0;
    glm::ivec2 full_{0};
    bool dirty_ = true;
    bool previewReady_ = false;
    bool fullReady_ = false;
    glm::ivec2 cursor_{0}; // the next tile's top-left pixel
};

} // namespace steerseg::kiosk
