#pragma once

// Outside examples from a surface the operator has accepted (docs/steering.md): when the
// classify speed takes over from the threshold while steering (the first erase), it learns what
// stopped that surface as well as the operator's spheres, instead of judging the tissue unlike
// its few examples by chance. What the surface took in is no evidence then: it is what an
// erase disputes (a leak took it). GL-free.
#include "core/volume.hpp"
#include "model/level_set_params.hpp"

#include <cstddef>
#include <glm/glm.hpp>
#include <span>
#include <vector>

namespace steerseg::speed {

// Where the front ran with a wider window (a correction's tissue level, model::TissueLevel):
// within `reach` voxels of `centre` it also took [low, high].
struct LocalWindow {
    glm::vec3 centre{0.0F};
    float reach = 0.0F;
    float low = 0.0F;
    float high = 0.0F;
};

struct ShellParams {
    // The shell: voxels with nearVoxels < phi <= farVoxels (phi in voxels, > 0 outside).
    float nearVoxels = 1.0F;
    float farVoxels = 3.0F;
    // The window the front ran with, and where it ran with a wider one. A voxel of the shell
    // that its window takes in was held back by curvature or a correction's reach, not by its
    // tissue, and is no example.
    float low = 0.0F;
    float high = 0.0F;
    std::span<const LocalWindow> local = {};
    std::size_t most = 512; // spheres, evenly spaced over the candidates in raster order
    float radius = 1.0F;    // each sphere's, in voxels
};

// The voxels of the shell whose value the window there refuses, at most params.most of them
// spread over the shell, as spheres of params.radius. phi: one float per voxel of the scan, i
// fastest. std::invalid_argument for a phi of another size, or parameters or windows that are
// not finite and ordered (near < far, low <= high, radius > 0, reach >= 0).
std::vector<model::Sphere> outsideShell(std::span<const float> phi, const Volume& scan,
                                        const ShellParams& params);

} // namespace steerseg::speed
