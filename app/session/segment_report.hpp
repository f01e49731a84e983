#pragma once

#include "session/session.hpp"

#include <cstdint>
#include <span>
#include <string>

namespace steerseg::session {

// What a segmentation run is reported with (README "segment"): the parameters, iterations,
// evolved time, solver seconds and rate, convergence, inside voxels and millilitres, the
// pool's peak and final storage against a dense level set, and the GL renderer. JSON text.
struct ReportContext {
    std::string input;
    std::string output;
    std::string renderer; // GL_RENDERER
    solver::LevelSetParams params;
};
// `mask`: session.mask() as exported (read back once by the caller).
std::string segmentReport(const Session& session, const RunOutcome& run,
                          std::span<const std::uint8_t> mask, const ReportContext& context);

} // namespace steerseg::session
