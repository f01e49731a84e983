#pragma once

// The session's structures as the workflow keeps them (docs/structures.md): the active one
// lives in the engine as its level set; every other one is kept compactly, as its mask's runs,
// with the parameters and counts it was left with, so a session of ten costs little more than
// its active one.
#include "core/mask_runs.hpp"
#include "model/structure.hpp"
#include "workflow/undo_stack.hpp"

#include <cstddef>
#include <optional>
#include <string_view>
#include <vector>

namespace steerseg::workflow {

struct Structure {
    model::StructureInfo info;
    // While another structure is active: its surface (no runs: none). The active one's is the
    // engine's level set, and this is empty.
    MaskRuns mask;
    ParamValues params; // the active one's: the workflow's own until it is left
    int seeds = 0;
    int erasures = 0;
    double volumeMl = 0.0; // when it was left
};

struct StructureList {
    std::vector<Structure> items; // in the order they were added: the exports' label order
    std::size_t active = 0;
    [[nodiscard]] std::optional<std::size_t> find(std::string_view name) const;
};

// Every inside voxel of the structures but `except` (no runs: none): what the active one may
// not grow into. Merges the runs themselves: no mask of the scan's size is drawn.
MaskRuns claimedBy(const StructureList& list, std::size_t except, std::size_t voxels);

} // namespace steerseg::workflow
