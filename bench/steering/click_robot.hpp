#pragma once

// The clicks protocol's robot operator (docs/steering.md), after the interactive 3D
// segmentation challenge at CVPR 2025: it looks at the expert label only to choose where to
// click. Pure functions on flat masks (non-zero inside, i fastest) with the scan's spacing in
// mm, so the rule is tested on synthetic masks without a GPU.
#include <cstddef>
#include <cstdint>
#include <glm/glm.hpp>
#include <optional>
#include <vector>

namespace steerseg::bench {

struct MaskGrid {
    glm::ivec3 dims{0};
    glm::dvec3 spacing{1.0}; // mm
    [[nodiscard]] std::size_t count() const {
        return static_cast<std::size_t>(dims.x) * static_cast<std::size_t>(dims.y) *
               static_cast<std::size_t>(dims.z);
    }
};

// The largest 26-connected component of `region`'s non-zero voxels (1 in it, else 0); of
// components of equal size, the one whose first voxel comes first in storage order. All zero
// when the region is empty.
std::vector<std::uint8_t> largestComponent(const MaskGrid& grid,
                                           const std::vector<std::uint8_t>& region);

struct RobotClick {
    glm::ivec3 voxel{0};
    bool positive = true; // the label holds the voxel: add; else remove
    double depthMm = 0.0; // its distance to the component's boundary
    std::size_t componentVoxels = 0;
};

// How far from a component's boundary a voxel lies, for choosing the click: in mm, as an
// operator sees the scan (the clicks protocol), or in voxel steps whatever the spacing, as the
// challenge's evaluation measures it (CVPR25_iter_eval.py: scipy's distance_transform_edt
// without a spacing; on 3 mm slices a step through them counts as much as one across them).
enum class DepthMeasure { Millimetres, VoxelSteps };

// The voxel of the largest component of `region` farthest from that component's boundary by
// `measure` (ties: the first in storage order; the challenge draws one at random), positive
// where `label` is non-zero; its depthMm is in mm either way. nullopt for an empty region.
std::optional<RobotClick> deepestClick(const MaskGrid& grid,
                                       const std::vector<std::uint8_t>& region,
                                       const std::vector<std::uint8_t>& label,
                                       DepthMeasure measure = DepthMeasure::Millimetres);
// The challenge's first prompt (issue 51): the label's bounding box, both corners inclusive
// voxel indices, over all its voxels (every component, as the challenge takes the label's
// extent). nullopt for an empty label.
struct VoxelBox {
    glm::ivec3 lo{0};
    glm::ivec3 hi{0};
};
std::optional<VoxelBox> labelBox(const MaskGrid& grid, const std::vector<std::uint8_t>& label);
// The first prompt without a box: the deepest voxel of the label's largest component.
std::optional<RobotClick> initialClick(const MaskGrid& grid,
                                       const std::vector<std::uint8_t>& label);
// A correction: the deepest voxel of the largest component of mask != label; nullopt when the
// mask is the label.
std::optional<RobotClick> correctionClick(const MaskGrid& grid,
                                          const std::vector<std::uint8_t>& mask,
                                          const std::vector<std::uint8_t>& label,
                                          DepthMeasure measure = DepthMeasure::Millimetres);

// The brush an operator would choose for a click: the largest sphere that stays inside the
// component in mm, its radius in voxels along the finest axis as the product's spheres are
// (model::Sphere), at least 1, at most `maxRadius`.
double brushRadius(const MaskGrid& grid, const RobotClick& click, double maxRadius);

// Dice of two masks' non-zero voxels (two empty masks agree: 1).
double dice(const std::vector<std::uint8_t>& a, const std::vector<std::uint8_t>& b);
// Normalised surface Dice at `toleranceMm`: the share of both surfaces' voxels (inside voxels
// with a face neighbour outside, or on the grid's edge) within the tolerance of the other
// surface. Two empty masks: 1; one empty: 0.
double surfaceDice(const MaskGrid& grid, const std::vector<std::uint8_t>& a,
                   const std::vector<std::uint8_t>& b, double toleranceMm);

// Paint-only's edit: every voxel of the sphere (model::Sphere's units) set to `value`.
void paintSphere(const MaskGrid& grid, std::vector<std::uint8_t>& mask, const glm::dvec3& centre,
                 double radius, std::uint8_t value);

// The area under the Dice curve over the first `points` predictions (trapezoid, unit steps:
// at most points - 1), as the challenge reports it; fewer predictions count what there is.
double diceAuc(const std::vector<double>& dices, std::size_t points = 6);

// The interactive challenge's scores of one structure (issue 51): step 0 is the initial prompt,
// steps 1..corrections its corrections. DSC_AUC and NSD_AUC are the trapezoid over the
// corrections' steps (at most corrections - 1), final DSC and NSD those after the last; an
// NSD counts 0 where its step's DSC is 0.2 or less. Fewer steps count what there is.
struct ChallengeScores {
    double dscAuc = 0.0;
    double nsdAuc = 0.0;
    double finalDsc = 0.0;
    double finalNsd = 0.0;
};
ChallengeScores challengeScores(const std::vector<double>& dices, const std::vector<double>& nsds,
                                std::size_t corrections = 5);

} // namespace steerseg::bench
