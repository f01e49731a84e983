#pragma once

#include "core/mask_overlap.hpp"
#include "session/session.hpp"

#include <cstdint>
#include <optional>
#include <span>
#include <string>

namespace steerseg::session {

// `segment --reference`: the label the mask was compared with, and how well they agree.
struct ReferenceOverlap {
    std::string file;
    int label = -1; // < 0: every non-zero voxel
    MaskOverlap overlap;
};

// What a segmentation run is reported with (README "segment"): the parameters, iterations,
// evolved time, solver seconds and rate, convergence, inside voxels and millilitres, the
// pool's peak and final storage against a dense level set, the GL renderer and, with a
// reference, the Dice against it. JSON text.
struct ReportContext {
    std::string input;
    std::string output;
    std::string renderer; // GL_RENDERER
    model::LevelSetParams params;
    std::optional<ReferenceOverlap> reference;
};
// No voxel of `mask` inside: the surface vanished, which the solver stops as it stops a converged
// front (nothing moves). The report's stop_reason is then "vanished" and the command says so.
bool surfaceVanished(std::span<const std::uint8_t> mask);

// `mask`: session.mask() as exported (read back once by the caller).
std::string segmentReport(const Session& session, const RunOutcome& run,
                          std::span<const std::uint8_t> mask, const ReportContext& context);

} // namespace steerseg::session
