#include "script/mask_dice.hpp"

#include "core/mask_overlap.hpp"
#include "scan/scan_reader.hpp"

#include <stdexcept>

namespace steerseg::script {

double maskDice(const std::filesystem::path& mask, const std::filesystem::path& reference,
                int label) {
    try {
        return maskOverlap(scan::readScan(mask).volume, scan::readScan(reference).volume, label)
            .dice();
    } catch (const std::invalid_argument& e) {
        throw std::runtime_error(mask.string() + " against " + reference.string() + ": " +
                                 e.what());
    }
}

} // namespace steerseg::script
