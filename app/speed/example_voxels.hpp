#pragma once

// The operator's examples for the classifier speed, and the training voxels they give. GL-free.
#include <cstddef>
#include <cstdint>
#include <glm/glm.hpp>
#include <span>
#include <string_view>
#include <vector>

namespace steerseg::speed {

// A probe sphere (or a stroke's dab): voxel indices, radius in voxels along the scan's finest
// axis (model::Sphere). A voxel belongs to it when its centre lies within the radius.
struct Example {
    glm::vec3 centre{0.0F};
    float radius = 0.0F;
};

struct ExampleVoxels {
    std::vector<glm::ivec3> voxels; // at most the cap, in raster order (i fastest)
    std::size_t covered = 0;        // voxels of the scan in the union of the spheres
};

// The voxels of the scan inside any of `examples` (each counted once), subsampled without
// replacement to at most `maxSamples` by a seeded reservoir, so the choice is spread over every
// sphere and the same for a seed. The cost follows the spheres' volume, not their number
// squared: a painted stroke brings thousands of overlapping dabs. `what` ("inside", "outside")
// names the class in messages; `scale` is what the radii are measured in (model::sphereScale).
// Throws std::invalid_argument for no examples, a centre or radius that is not finite, a
// negative radius, or examples that cover no voxel of the scan.
ExampleVoxels exampleVoxels(std::span<const Example> examples, glm::ivec3 dims,
                            std::size_t maxSamples, std::uint64_t seed, std::string_view what,
                            const glm::vec3& scale = glm::vec3(1.0F));

} // namespace steerseg::speed
