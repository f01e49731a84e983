#pragma once

#include "core/volume.hpp"
#include "gpu/gl_handle.hpp"
#include "gpu/scan_texture.hpp"

#include <glm/glm.hpp>
#include <vector>

namespace steerseg::render {

inline constexpr int kSkipBlock = 8; // voxels per side of an empty-space-skipping block

// The ray caster's empty-space-skipping grid: per block of kSkipBlock voxels, the min and max
// normalised intensity (RG16F), including a one-voxel apron since trilinear samples reach into
// neighbours. Built a layer of blocks at a time, so the host holds kSkipBlock + 2 slices.
class SkipGrid {
  public:
    SkipGrid(const Volume& volume, const gpu::ScanTexture& scan);
    [[nodiscard]] GLuint texture() const { return texture_.id(); }
    [[nodiscard]] glm::ivec3 dims() const { return dims_; }

  private:
    glm::ivec3 dims_{0};
    gpu::Texture texture_;
};

// Per-block min/max of `values` (dims, i fastest) over blocks of kSkipBlock voxels grown by
// one voxel on each side; interleaved (min, max), block x fastest. Exposed for tests.
std::vector<float> blockMinMax(const std::vector<float>& values, const glm::ivec3& dims);

} // namespace steerseg::render
