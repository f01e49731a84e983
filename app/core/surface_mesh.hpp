#pragma once

// The segmentation's boundary as a closed triangle mesh: what the STL and PLY exports write and
// what a mask's surface area is measured on (core/mask_measurements), so the two agree.
#include "core/volume.hpp"

#include <array>
#include <cstdint>
#include <glm/glm.hpp>
#include <span>
#include <vector>

namespace steerseg {

// An indexed triangle mesh in world coordinates (LPS millimetres). Triangles wind
// counter-clockwise seen from outside, so their right-hand normals point out of the region.
struct SurfaceMesh {
    std::vector<glm::dvec3> vertices;
    std::vector<std::array<std::uint32_t, 3>> triangles;

    [[nodiscard]] bool empty() const { return triangles.empty(); }
};

// The zero level set of `phi` (one value per voxel of `geometry`, i fastest; phi < 0 inside,
// any positive scale), by marching tetrahedra: each cube of eight neighbouring voxel centres is
// cut into six tetrahedra around its main diagonal, the same way in every cube, so neighbouring
// cubes agree on their shared faces and the mesh has no cracks and no ambiguous cases. A vertex
// sits where phi crosses zero along a grid edge (linear interpolation), so the surface is
// sub-voxel, not the voxel staircase. Vertices are shared between the triangles of an edge,
// and the field is treated as outside beyond the grid, so the mesh is always closed; where the
// region touches the grid's border the surface closes half a voxel beyond the last voxel
// centre, on the voxels' outer face. A NaN counts as outside. Throws std::invalid_argument when
// phi's size is not the geometry's voxel count.
SurfaceMesh extractSurface(const Geometry& geometry, std::span<const float> phi);

// The area of the mesh's triangles, in square millimetres.
double surfaceArea(const SurfaceMesh& mesh);

// The volume the mesh encloses (divergence theorem), in cubic millimetres; positive for a
// closed mesh whose normals point outward.
double enclosedVolume(const SurfaceMesh& mesh);

} // namespace steerseg
