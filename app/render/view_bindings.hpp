#pragma once

#include "core/volume.hpp"
#include "gpu/gl_handle.hpp"
#include "gpu/program.hpp"
#include "gpu/scan_texture.hpp"
#include "render/render_params.hpp"
#include "render/render_target.hpp"
#include "render/skip_grid.hpp"
#include "solver/brick_pool_view.hpp"
#include "speed/speed_inputs.hpp"

#include <string>

namespace steerseg::render {

// What both views read: the scan, its skipping grid, its geometry, the level set (may be
// null), where to draw.
struct RenderInputs {
    const gpu::ScanTexture& scan;
    const SkipGrid& skip;
    const Geometry& geometry;
    const solver::BrickPoolView* pool;
    GLuint emptyBuffer; // bound in place of the pool when there is none
    const RenderTarget& target;
    GLuint gradient;                 // GradientTexture, 0 when the scan has none
    const speed::SpeedInputs& speed; // the speed view's data term, and the 3D view's surface's
};

// A compute program built for the pool's BRICK_SIZE / PHI_FAR, rebuilt when they change;
// `defines` choose a variant of the shader.
class PoolProgram {
  public:
    explicit PoolProgram(std::string shader, gpu::Defines defines = {})
        : shader_(std::move(shader)), defines_(std::move(defines)) {}
    GLuint get(const solver::BrickPoolView* pool);

  private:
    std::string shader_;
    gpu::Defines defines_;
    gpu::Program program_;
    int brickSize_ = 0;
    float phiFar_ = 0.0F;
};

// Binds the scan (texture unit 0), the pool SSBOs (0, 1), the target (image unit 0) and sets
// the uniforms of shaders/render/view_common.glsl. The program must be current.
void bindCommon(GLuint program, const RenderInputs& in, const ViewParams& params);

// Dispatches one invocation per pixel of params.region (the whole picture by default; 8x8 work
// groups) and orders the writes before reads. The rest of the picture keeps what it held.
void dispatchRegion(GLuint program, const ViewParams& params);

GLint uniform(GLuint program, const char* name);

} // namespace steerseg::render
