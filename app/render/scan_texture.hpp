#pragma once

#include "core/volume.hpp"
#include "gpu/gl_handle.hpp"

#include <glm/glm.hpp>
#include <vector>

namespace steerseg::render {

inline constexpr int kSkipBlock = 8; // voxels per side of an empty-space-skipping block

// The scan on the GPU for display: a filterable R16F 3D texture of intensity normalised to
// [0, 1] over the scan's real-unit [min, max] (half floats keep 11 significant bits, enough
// for a 12-bit CT window of a few HU, where R8 would band; R16F is filterable in GLES 3.x,
// 16-bit integer formats are not), and a coarse RG16F grid of per-block min/max (including a
// one-voxel apron, since trilinear samples reach into neighbours) for empty-space skipping.
// With the solver's exact R32F texture of the same scan (`shared`, real units) and a driver
// that filters float textures (GL_OES_texture_float_linear), that texture is displayed instead
// and no copy is uploaded: the scan is on the GPU once. Shaders map a texture value v to
// normalised intensity as v * toNormalised().x + toNormalised().y.
class ScanTexture {
  public:
    // `shared`: LevelSetSolver::scanTexture() for this volume, which must outlive this object,
    // or 0.
    explicit ScanTexture(const Volume& volume, GLuint shared = 0);

    [[nodiscard]] GLuint texture() const { return shared_ != 0 ? shared_ : texture_.id(); }
    [[nodiscard]] bool sharesSolverTexture() const { return shared_ != 0; }
    [[nodiscard]] glm::vec2 toNormalised() const;
    [[nodiscard]] GLuint minMaxGrid() const { return grid_.id(); }
    [[nodiscard]] glm::ivec3 dims() const { return dims_; }
    [[nodiscard]] glm::ivec3 gridDims() const { return gridDims_; }
    [[nodiscard]] double rangeMin() const { return min_; }
    [[nodiscard]] double rangeMax() const { return max_; }
    [[nodiscard]] double normalise(double real) const;

  private:
    GLuint shared_ = 0;
    gpu::Texture texture_;
    gpu::Texture grid_;
    glm::ivec3 dims_{0};
    glm::ivec3 gridDims_{0};
    double min_ = 0.0;
    double max_ = 1.0;
};

// Per-block min/max of `values` (dims, i fastest) over blocks of kSkipBlock voxels grown by
// one voxel on each side; interleaved (min, max), block x fastest. Exposed for tests.
std::vector<float> blockMinMax(const std::vector<float>& values, const glm::ivec3& dims);

} // namespace steerseg::render
