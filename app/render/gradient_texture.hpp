#pragma once

#include "gpu/gl_handle.hpp"
#include "gpu/scan_texture.hpp"

#include <cstddef>

namespace steerseg::render {

// The scan's gradient for the 3D view (shaders/render/gradient.comp), computed once per scan,
// with the normalised intensity beside it: one linearly filtered fetch per sample for both
// instead of seven. RGBA32F (16 bytes per voxel) where the budget allows, else RGBA16F (8). A
// scan whose gradient would exceed the texture limits or the memory budget even in half floats
// gets none (the ray caster then differences the scan per sample, slower but the same
// picture), so a large scan still renders.
class GradientTexture {
  public:
    // Bytes of gradient allowed before the ray caster falls back to per-sample differences.
    static constexpr std::size_t kDefaultBudget = std::size_t{1} << 30;

    explicit GradientTexture(const gpu::ScanTexture& scan, std::size_t budget = kDefaultBudget);
    [[nodiscard]] bool available() const { return static_cast<bool>(texture_); }
    [[nodiscard]] GLuint texture() const { return texture_.id(); }
    [[nodiscard]] std::size_t bytes() const { return bytes_; }

  private:
    gpu::Texture texture_;
    std::size_t bytes_ = 0;
};

} // namespace steerseg::render
