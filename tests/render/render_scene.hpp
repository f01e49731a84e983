#pragma once

#include "core/rgba_image.hpp"
#include "core/volume.hpp"
#include "support/pool_packer.hpp"

#include <filesystem>
#include <glm/glm.hpp>
#include <string>

namespace steerseg::test {

// Small synthetic scans for the renderer tests (fast on llvmpipe).

// A float32 scan of `dims` (1 mm voxels unless `geometry` says otherwise) filled by f(index).
Volume makeScan(const Geometry& geometry, const std::function<float(glm::ivec3)>& f);

// A head-like scene: an ellipsoid "head" (300) around a "brain" (500), a bright "lesion"
// sphere (900) off-centre towards +i, +k, -j. 48 x 48 x 40 voxels, 1.2 x 1.2 x 1.5 mm.
Volume makeHeadScene();
inline constexpr glm::dvec3 kHeadLesionCentre{31.0, 19.0, 23.0};
inline constexpr double kHeadLesionRadius = 7.0; // voxels

// Signed distance (voxels) to a sphere in index space: the test's analytic level set.
PackedPool spherePool(const glm::ivec3& dims, const glm::dvec3& centre, double radius,
                      int brickSize = 8, float phiFar = 4.0F);

// Pixel colour helpers.
bool isYellow(const std::uint8_t* px);
bool isBlack(const std::uint8_t* px);

} // namespace steerseg::test
