#pragma once

#include "core/volume.hpp"
#include "gpu/scan_texture.hpp"

#include <cstddef>
#include <cstdint>
#include <glm/glm.hpp>
#include <span>
#include <vector>

namespace steerseg::render {

// Intensity bands per block: kTfIntensityBins / kSkipBands transfer-function bins each.
inline constexpr int kSkipBands = 32;

// Host memory the skipping grid may take; its blocks are as small as that allows (2, 4 or 8
// voxels a side; 8 regardless of size).
inline constexpr std::size_t kSkipGridBudget = std::size_t{64} << 20;

// The ray caster's empty-space skipping, per block of blockSize() voxels: for each intensity
// band, the largest gradient magnitude (normalised intensity per voxel, as render/gradient.comp
// computes it) of a trilinear cell whose intensities reach into the band, or -1 where none
// does. A sample lies in one cell: its intensity within the cell's corners' range, its gradient
// (the trilinear blend of theirs) no longer than their longest. So a block is skipped when, in
// every band it reaches, no transfer-function texel up to its gradient there is occupied
// (visibleBlocks). Per band rather than one intensity range and largest gradient per block:
// the tissue's noise then counts only at its own intensities, where a gradient-gated transfer
// function draws nothing, not beside a boundary's intensities. Small blocks because such noise
// peaks are sparse but present in most blocks of 8 voxels (the built-in sample's MR transfer
// function draws them faintly). Built a layer of blocks at a time, so the host holds
// blockSize() + 6 slices.
class SkipGrid {
  public:
    SkipGrid(const Volume& volume, const gpu::ScanTexture& scan,
             std::size_t budget = kSkipGridBudget);
    [[nodiscard]] glm::ivec3 dims() const { return dims_; }
    [[nodiscard]] int blockSize() const { return block_; }
    // Per block (x fastest): 1 where a sample may be visible under the transfer function whose
    // occupancy table (occupancyTable()) and gradient scale are given, else 0.
    [[nodiscard]] std::vector<std::uint8_t> visibleBlocks(const std::vector<float>& occupancy,
                                                          double gradientScale) const;

  private:
    int block_ = 8;
    glm::ivec3 dims_{0};
    std::vector<float> bands_; // kSkipBands per block
};

// The per-block band maxima of `values` (normalised intensity, dims, i fastest) for blocks of
// `block` voxels: kSkipBands floats a block, block x fastest. The cells of block b are those
// holding samples whose block is b (p in [block b - 0.5, block (b + 1) - 0.5) per axis), corners
// clamped to the volume. Exposed for tests.
std::vector<float> blockBands(const std::vector<float>& values, const glm::ivec3& dims, int block);

// Whether one block's band maxima (kSkipBands floats) may hold a visible sample: the test
// visibleBlocks() makes of each block.
bool bandsVisible(const float* bands, const std::vector<float>& occupancy, double gradientScale);

// Per block of `block` voxels (SkipGrid's layout, x fastest): 1 where some voxel of `labels`
// (dims, i fastest) is non-zero. The ray caster finds the other structures' surfaces in its march
// by their voxels' labels (render/structure_labels.hpp), so these blocks are not skipped however
// empty the transfer function leaves them: a sample's nearest voxel lies in the sample's block.
std::vector<std::uint8_t> labelledBlocks(std::span<const std::uint8_t> labels,
                                         const glm::ivec3& dims, int block);

} // namespace steerseg::render
