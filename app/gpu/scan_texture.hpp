#pragma once

#include "core/volume.hpp"
#include "gpu/gl_handle.hpp"

#include <glm/glm.hpp>
#include <span>

namespace steerseg::gpu {

// The scan on the GPU, owned once and borrowed by the solver and the renderer: an R32F 3D
// texture of real-unit intensities. The solver reads it exactly (texelFetch); the renderer
// samples it with linear filtering where the driver filters float textures
// (GL_OES_texture_float_linear). Where it does not, a filterable R16F copy normalised to
// [0, 1] over the scan's range is kept for display (half floats keep 11 significant bits,
// enough for a 12-bit CT window of a few HU; R16F is filterable in every GLES 3.x). Shaders map
// a display-texture value v to normalised intensity as v * toNormalised().x + toNormalised().y.
// Uploads go in slabs of slices, so the host never holds a float copy of the whole scan.
// Needs a current GLES 3.1 context for its whole life.
enum class ScanDisplay {
    Auto,          // the exact texture where floats filter linearly, else a half-float copy
    HalfFloatCopy, // always the copy (what drivers without float filtering get; for tests)
};

class ScanTexture {
  public:
    // Throws std::runtime_error when the scan exceeds the GPU's 3D texture size.
    explicit ScanTexture(const Volume& volume, ScanDisplay display = ScanDisplay::Auto);
    // Real-unit intensities, i fastest (tests and benchmarks on synthetic volumes).
    ScanTexture(std::span<const float> intensities, const glm::ivec3& dims);
    ScanTexture(const ScanTexture&) = delete;
    ScanTexture& operator=(const ScanTexture&) = delete;

    [[nodiscard]] GLuint exact() const { return exact_.id(); }
    [[nodiscard]] GLuint display() const { return display_ ? display_.id() : exact_.id(); }
    [[nodiscard]] bool displaysExact() const { return !display_; }
    [[nodiscard]] glm::vec2 toNormalised() const;
    [[nodiscard]] glm::ivec3 dims() const { return dims_; }
    // The voxel size in millimetres (1, 1, 1 for a texture made from bare intensities).
    [[nodiscard]] glm::dvec3 spacing() const { return spacing_; }
    [[nodiscard]] double rangeMin() const { return min_; }
    [[nodiscard]] double rangeMax() const { return max_; }
    // Real units -> [0, 1] over the scan's range.
    [[nodiscard]] double normalise(double real) const;

  private:
    template <typename SliceSource> void upload(const SliceSource& slices, ScanDisplay display);

    glm::ivec3 dims_{0};
    glm::dvec3 spacing_{1.0};
    double min_ = 0.0;
    double max_ = 1.0;
    Texture exact_;
    Texture display_;
};

} // namespace steerseg::gpu
