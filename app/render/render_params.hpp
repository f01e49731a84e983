#pragma once

#include "render/camera.hpp"
#include "render/transfer_function.hpp"

#include <glm/glm.hpp>

namespace steerseg::render {

enum class ViewKind { Volume3d, Axial, Coronal, Sagittal };
// How the level-set surface acts as a region of interest for the scan's volume rendering.
enum class RoiMode { Off, Inside, Dim };
enum class SurfaceMode { Hidden, Opaque, Translucent };
// What a slice view shows under the contour: the scan, or the data term of the speed function.
enum class SliceContent { Scan, Speed };

// Display mapping of real-unit intensities to grey: [level - width/2, level + width/2] -> [0, 1].
struct WindowLevel {
    double level = 0.0;
    double width = 1.0;
};

// The clipping plane n . (i, j, k) = d in voxel indices; the half-space n . p > d is cut away.
struct ClipPlane {
    bool enabled = false;
    glm::dvec3 normal{0.0, 0.0, 1.0};
    double d = 0.0;
};

// The data term of the segmentation speed: D(I) = eps - |I - T| (real units) for the threshold
// and edge speeds; classify's reads neither.
struct SpeedParams {
    double T = 0.0;
    double eps = 1.0;
    // The level set drawn was moved by this data term (the solver's own, with this T and eps):
    // where phi is a step, the 3D view puts the surface at the term's zero crossing near
    // phi's (shaders/render/surface_smooth.glsl). False for a mask from elsewhere, whose
    // boundary no speed drew.
    bool placesSurface = false;
};

// Everything one frame depends on. Plain data so the UI can keep one per view.
struct ViewParams {
    ViewKind kind = ViewKind::Volume3d;
    glm::ivec2 size{256, 256};
    Camera camera;              // 3D view
    TransferFunction transfer;  // 3D view
    WindowLevel window;         // slices and the textured clip plane
    ClipPlane clip;             // 3D view
    RoiMode roi = RoiMode::Off; // 3D view
    SurfaceMode surface = SurfaceMode::Opaque;
    float dimFactor = 0.15F; // RoiMode::Dim: opacity kept outside the surface
    int slice = -1;          // slice views: index along the view's axis; -1 = middle
    double zoom = 1.0;       // slice views: 1 = the slice fits the image
    glm::dvec2 pan{0.0};     // slice views: centre offset in mm (screen right, up)
    SliceContent content = SliceContent::Scan;
    SpeedParams speed;
    bool contour = true; // slice views: yellow contour of phi = 0
    bool labels = true;  // slice views: orientation letters
    // Which of the renderer's pictures to draw into (0..kRenderTargets-1). A screen that shows
    // several views keeps one picture each, so a 3D view refined over several frames survives
    // the slice views drawn in between.
    int target = 0;
    // Draw only this part of the picture (x, y of the top-left pixel, width, height) and keep
    // the rest as it was, so a picture too slow for one frame is drawn over several.
    // width < 0 = the whole picture.
    glm::ivec4 region{0, 0, -1, -1};
};

inline constexpr int kRenderTargets = 6;

} // namespace steerseg::render
