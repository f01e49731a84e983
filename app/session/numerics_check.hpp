#pragma once

// The appliance checks its GPU's numbers itself (issue 47): each speed the solver can step with,
// computed on this GPU over a small built-in phantom and held voxel for voxel against its CPU
// twin, then a few solver iterations against the dense CPU reference. A driver that computes
// wrong numbers (the classify speed's features on an NVIDIA driver, docs/speed.md) fails its
// speed here, at `steerseg --self-test` and at the kiosk's start, instead of giving an operator
// a wrong mask. Under 2 s on llvmpipe.
#include "model/speed_kind.hpp"

#include <string>
#include <vector>

namespace steerseg::session {

struct SpeedNumerics {
    model::SpeedKind kind = model::SpeedKind::Threshold;
    bool passed = false;
    // The largest |GPU - CPU| over the speed's values (the data term the solver reads) and the
    // textures behind it; infinite where the GPU returned a value that is not a number.
    double largestDifference = 0.0;
    std::string detail;  // one line: what was compared and how far apart
    std::string failure; // what failed, one line ("" when it passed)
};

struct NumericsReport {
    std::vector<SpeedNumerics> speeds; // one per model::kSpeedKinds, in that order
    double seconds = 0.0;
    [[nodiscard]] bool passed(model::SpeedKind kind) const;
    [[nodiscard]] bool allPassed() const;
};

// Needs a current GLES 3.1 context. Never throws for what the GPU does: a GL error or a refusal
// inside a speed's check fails that speed with its message.
NumericsReport checkGpuNumerics();

} // namespace steerseg::session
