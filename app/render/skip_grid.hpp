#pragma once

#include "core/volume.hpp"
#include "gpu/gl_handle.hpp"
#include "gpu/scan_texture.hpp"

#include <glm/glm.hpp>
#include <vector>

namespace steerseg::render {

inline constexpr int kSkipBlock = 8; // voxels per side of an empty-space-skipping block

inline constexpr int kSkipRangeChannels = 4; // min, max intensity, unused, max |gradient|

// The ray caster's empty-space-skipping grid: per block of kSkipBlock voxels, the min and max
// normalised intensity and the largest gradient magnitude (normalised intensity per voxel, as
// render/gradient.comp computes it) (RGBA16F), including a one-voxel apron since trilinear
// samples reach into neighbours. With the gradient, a block of homogeneous tissue under a
// gradient-gated transfer function is skipped although its intensities are visible at edges.
// Built a layer of blocks at a time, so the host holds kSkipBlock + 4 slices.
class SkipGrid {
  public:
    SkipGrid(const Volume& volume, const gpu::ScanTexture& scan);
    [[nodiscard]] GLuint texture() const { return texture_.id(); }
    [[nodiscard]] glm::ivec3 dims() const { return dims_; }

  private:
    glm::ivec3 dims_{0};
    gpu::Texture texture_;
};

// Per-block ranges of `values` (dims, i fastest) over blocks of kSkipBlock voxels grown by one
// voxel on each side: kSkipRangeChannels floats a block (min, max, 0, max |gradient|), block x
// fastest. Exposed for tests.
std::vector<float> blockRanges(const std::vector<float>& values, const glm::ivec3& dims);

} // namespace steerseg::render
