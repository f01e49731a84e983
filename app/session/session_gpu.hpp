#pragma once

// Session::Gpu, shared by the session's own .cpp files (session.cpp, session_speed.cpp) and
// by no other module: session.hpp names no GL type, so the GL context's contents stay here.

#include "gpu/gl_handle.hpp"
#include "gpu/scan_texture.hpp"
#include "model/solver_types.hpp"
#include "render/renderer.hpp"
#include "session/session.hpp"
#include "session/speed_settings.hpp"
#include "solver/level_set_solver.hpp"
#include "speed/classifier_speed.hpp"
#include "speed/smoothing.hpp"

#include <optional>

namespace steerseg::session {

// Everything that lives in the GL context, in the order it must be built and torn down: the
// scan texture outlives the solver and the renderer that borrow it.
struct Session::Gpu {
    Gpu(const Volume& scan, const model::SolverOptions& options)
        : texture(scan), solver(texture, options), renderer(scan, texture) {}
    gpu::ScanTexture texture;
    solver::LevelSetSolver solver;
    render::Renderer renderer;
    // The speed's textures (Session::setSpeed), borrowed by the solver.
    gpu::Texture smoothed; // empty: the speed reads the raw scan
    speed::SmoothingParams smoothedWith;
    gpu::Texture factor;                              // edge: g
    std::optional<speed::ClassifierSpeed> classifier; // classify: P(inside) - P(outside)
    SpeedSettings speed;
    SpeedTiming timing;
};

} // namespace steerseg::session
