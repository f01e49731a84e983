// The engine's side of the session's structures (docs/structures.md): the level set as a mask
// when the operator leaves a structure, the other structures' voxels as the solver's claimed
// barrier, and the export of all of them at once.
#include "engine/session_engine.hpp"

#include <stdexcept>

namespace steerseg::engine {

MaskRuns SessionEngine::levelSetMask() const {
    const session::Session& s = requireSession();
    return s.hasLevelSet() ? encodeRuns(s.mask()) : MaskRuns{};
}

MaskMeasurements SessionEngine::measureStructure(const MaskRuns* mask) const {
    const session::Session& s = requireSession();
    return measureMask(s.scan(), mask != nullptr ? decodeRuns(*mask) : s.mask());
}

void SessionEngine::setClaimed(const MaskRuns& claimed) {
    session::Session& s = requireSession();
    if (claimed.runs.empty()) {
        s.setClaimed({});
    } else {
        s.setClaimed(decodeRuns(claimed));
    }
    changed();
}

std::vector<std::filesystem::path>
SessionEngine::exportStructures(const std::filesystem::path& path,
                                const std::vector<workflow::ExportedStructure>& structures) {
    // The masks decoded here live until the write returns; the layers only point at them.
    std::vector<std::vector<std::uint8_t>> masks;
    masks.reserve(structures.size());
    std::vector<exports::StructureLayer> layers;
    std::optional<std::size_t> levelSet;
    for (const workflow::ExportedStructure& s : structures) {
        exports::StructureLayer layer;
        layer.segment.name = s.info.name;
        layer.segment.color = s.info.colour;
        layer.segment.label = s.label;
        layer.category = {s.info.category.value, s.info.category.scheme, s.info.category.meaning};
        layer.type = {s.info.type.value, s.info.type.scheme, s.info.type.meaning};
        if (s.mask == nullptr) {
            levelSet = layers.size();
        } else {
            masks.push_back(decodeRuns(*s.mask));
            layer.mask = masks.back();
        }
        layers.push_back(std::move(layer));
    }
    return requireSession().exportStructures(path, std::move(layers), levelSet);
}

} // namespace steerseg::engine
