#pragma once

#include "gpu/gl_handle.hpp"
#include "gpu/program.hpp"

#include <string>

namespace steerseg::solver::detail {

// Invocations per group of the passes that take one group a brick, for bricks of `brickSize`:
// `requested` if not 0, else the one for the device named `renderer` (GL_RENDERER; why:
// solver_programs.cpp).
int brickGroupSize(int brickSize, int requested, const std::string& renderer);

// The constants every solver pass is compiled with (brick size, work-group size, PHI_FAR...).
gpu::Defines solverDefines(int brickSize, int localSize);

// The solver's compute passes (shaders/solver/*.comp), compiled for one brick size. Binding
// points and the control block layout are shared with shaders/solver/solver_common.glsl.
struct SolverPrograms {
    gpu::Program beginIteration;
    gpu::Program allocateBricks;
    gpu::Program buildActiveList;
    gpu::Program measureSpeed;
    gpu::Program updatePhi;
    gpu::Program settleBricks;
    gpu::Program classifyBricks;
    gpu::Program requestEditBricks;
    gpu::Program applySphere;
    int localSize; // invocations per group of the per-brick passes

    SolverPrograms(int brickSize, int localSize);

    // Calls f(program) for each program (to set uniforms shared by all).
    template <typename F> void forEach(F&& f) {
        for (gpu::Program* p :
             {&beginIteration, &allocateBricks, &buildActiveList, &measureSpeed, &updatePhi,
              &settleBricks, &classifyBricks, &requestEditBricks, &applySphere}) {
            f(*p);
        }
    }
};

} // namespace steerseg::solver::detail
