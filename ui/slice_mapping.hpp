#pragma once

// A pixel of a slice view on the screen -> the voxel under it. The renderer describes each
// slice image by a render::SliceFrame (voxel position = origin + x * stepRight + y * stepDown
// for pixel (x, y) of an image of `renderSize`); the kiosk may render at a lower resolution
// than the rect it shows the image in, so screen pixels scale to image pixels first.
#include "model/box.hpp"
#include "render/slice_frame.hpp"
#include "ui/layout.hpp"

#include <glm/glm.hpp>
#include <optional>

namespace steerseg::ui {

// One slice view as drawn this frame.
struct SliceView {
    render::SliceFrame frame;
    glm::ivec2 renderSize{0}; // the image the frame was computed for
    Rect rect;                // where the image is shown, logical pixels
};

// Continuous voxel-index position under logical screen point `p` (pixel centres at +0.5);
// nullopt outside the rect or for an empty view. The slice axis component is the slice index.
std::optional<glm::dvec3> voxelAtScreen(const SliceView& view, const glm::dvec2& p);

// Where a voxel-index position projects on the screen (its in-plane part; the inverse of
// voxelAtScreen for points on the slice).
glm::dvec2 screenOfVoxel(const SliceView& view, const glm::dvec3& voxel);

// Where the view's slice cuts `box`, on the screen: the rectangle's corners (min, max in screen
// pixels), its edges on the voxels' outer boundaries (half a voxel beyond lo and hi); nullopt
// where the slice misses the box.
struct ScreenBox {
    glm::dvec2 min{0.0};
    glm::dvec2 max{0.0};
};
std::optional<ScreenBox> boxOnScreen(const SliceView& view, const model::Box& box);

// Whether a continuous voxel position lies within the scan (voxel centres are integers, so the
// scan spans -0.5 .. dims - 0.5 on each axis).
bool insideScan(const glm::dvec3& voxel, const glm::ivec3& dims);

} // namespace steerseg::ui
