#pragma once

#include "core/volume.hpp"
#include "render/render_params.hpp"

#include <array>
#include <glm/glm.hpp>

namespace steerseg::render {

// Where a slice view's pixels sit in voxel-index space, and which patient side each image
// edge faces. Screen directions in world LPS (radiological convention):
//   axial: right = patient left (+x), up = anterior (-y)  (looking from the feet)
//   coronal: right = patient left (+x), up = superior (+z) (looking from the front)
//   sagittal: right = posterior (+y), up = superior (+z)  (looking from the patient's left)
// The slice is a plane of constant index along the index axis closest to the view's normal;
// the in-plane index axes go to the screen axis they are closest to, flipped as needed, so
// the image is exact for axis-aligned scans (any permutation or flip of the axes) and the
// nearest such view of an oblique one.
struct SliceFrame {
    int sliceAxis = 2;         // index axis held constant
    int slice = 0;             // its index
    int axisU = 0;             // index axis running left-right on screen
    int axisV = 1;             // index axis running top-bottom
    glm::dvec3 origin{0.0};    // voxel-index position of pixel (0, 0)'s centre
    glm::dvec3 stepRight{0.0}; // voxel-index step per pixel to the right
    glm::dvec3 stepDown{0.0};  // voxel-index step per pixel downwards
    double pixelMm = 1.0;
    // Letters at the left, right, top and bottom edges: one of "RLAPSI".
    std::array<char, 4> labels{'?', '?', '?', '?'};
};

// Throws std::invalid_argument for a 3D view kind, a slice outside the volume, or a
// non-positive zoom / size. params.slice < 0 means the middle slice.
SliceFrame sliceFrame(const Geometry& geometry, const ViewParams& params);

// Letter of the patient side a world (LPS) direction points to most: L R P A S I.
char patientSide(const glm::dvec3& worldDirection);

// Index axis along which a slice view of `kind` steps (for --slice validation).
int sliceAxisFor(const Geometry& geometry, ViewKind kind);

} // namespace steerseg::render
