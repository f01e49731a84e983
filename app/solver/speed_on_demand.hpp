#pragma once

#include "gpu/gl_handle.hpp"
#include "speed/speed_inputs.hpp"

#include <cstdint>
#include <glm/glm.hpp>

namespace steerseg::solver::detail {

// The solver's half of the classifier speed evaluated where the front goes (docs/speed.md,
// "Evaluation", "Where the front goes"): which bricks already hold their speed in the factor
// texture, and the pass that fills the others (shaders/solver/evaluate_speed.comp). Built when
// a speed that needs it arrives, so a solver that never classifies compiles nothing more.
class SpeedOnDemand {
  public:
    SpeedOnDemand(const glm::ivec3& dims, const glm::ivec3& brickGrid, int brickSize,
                  int localSize);

    // Every brick to be evaluated again (a new forest or factor texture).
    void reset();
    // The forest, the ready words and inputs.factor as the image the passes write. The features'
    // intensity must be bound at SPEED_SOURCE_UNIT (speed::bindSpeedTextures binds it there).
    void bind(const speed::SpeedInputs& inputs) const;
    // The active list's bricks that lack their speed, from the solver's indirect arguments at
    // `argsOffset` of the bound GL_DISPATCH_INDIRECT_BUFFER. Needed after a wake only (every
    // brick of the band may then step): a brick the band reaches later gets its speed where
    // it is allocated (allocate).
    void evaluateActive(GLintptr argsOffset) const;
    // The solver's allocation pass (allocate_bricks.comp) that also evaluates each new brick's
    // speed, over the requests at `argsOffset`: an iteration's only dispatch for the speed.
    void allocate(GLintptr argsOffset) const;
    // Up to maxBricks further bricks in index order, whatever the front does (a speed view of
    // the whole scan, filled a little per frame); returns the bricks not yet visited this way.
    std::uint32_t evaluateAhead(std::uint32_t maxBricks);
    [[nodiscard]] std::uint32_t aheadLeft() const { return bricks_ - aheadCursor_; }
    // Bricks evaluated since the last reset, either way (one word read back).
    [[nodiscard]] std::uint32_t evaluatedBricks() const;

  private:
    void finishPass() const;

    gpu::Program program_;
    gpu::Program allocate_; // allocate_bricks.comp with EVALUATE_SPEED
    gpu::Buffer ready_;     // [0] the count, [1 + brick] non-zero once stored
    std::uint32_t bricks_;
    std::uint32_t aheadCursor_ = 0;
    glm::ivec3 dims_;
};

} // namespace steerseg::solver::detail
