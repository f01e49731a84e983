#pragma once

// Where the operator's marks say a voxel belongs, for the classifier speed (issue 27,
// docs/speed.md "Where appearance is unsure, the marks decide"): appearance cannot tell a tumour
// from the tissue of its leak, but the operator's marks tell where each lies. A mark speaks only
// near itself, fading to nothing at `reach` of its radii, so that a voxel far from every mark is
// decided by its appearance alone. GL-free.
#include "speed/example_voxels.hpp"

#include <glm/glm.hpp>
#include <span>
#include <vector>

namespace steerseg::speed {

// Voxels a side of one cell of the vote's grid: the vote changes over a mark's radius or more,
// so a coarse grid, linearly interpolated, carries it at 1/64 of the scan's texels.
inline constexpr int kPlaceVoteCell = 4;

struct PlaceVote {
    glm::ivec3 dims{0};        // cells a side: ceil(scan dims / kPlaceVoteCell)
    std::vector<float> values; // raster order (i fastest), each in [-1, 1]
};

// One mark's weight at distance d (in its radius's units, model::Sphere) from its centre: 1 within
// its radius, falling linearly to 0 at reach x radius (radius at least half a voxel); reach <= 1: 1
// within the radius, 0 beyond.
float placeWeight(float distance, float radius, float reach);

// At the centre of each cell: the strongest inside mark's weight less the strongest outside
// mark's (the strongest, not the sum, so that a stroke's thousands of overlapping dabs speak as
// one mark). Reach 0: no mark votes (appearance alone). The cost follows the marks' reach, not
// the scan. Throws std::invalid_argument for dims below 1, a reach that is not finite or
// negative, or a mark whose centre or radius is not finite or whose radius is negative.
PlaceVote placeVote(std::span<const Example> inside, std::span<const Example> outside,
                    glm::ivec3 dims, float reach, const glm::vec3& scale = glm::vec3(1.0F));

// The vote at voxel v as the GPU reads it (speed/classifier_forest.glsl): linear between cell
// centres, the edge cells' values beyond them.
float placeVoteAt(const PlaceVote& vote, glm::ivec3 v);

} // namespace steerseg::speed
