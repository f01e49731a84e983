#include "kiosk/mask_dice.hpp"

#include "core/mask_overlap.hpp"
#include "io/scan_reader.hpp"

#include <stdexcept>

namespace steerseg::kiosk {

double maskDice(const std::filesystem::path& mask, const std::filesystem::path& reference,
                int label) {
    try {
        return maskOverlap(io::readScan(mask).volume, io::readScan(reference).volume, label).dice();
    } catch (const std::invalid_argument& e) {
        throw std::runtime_error(mask.string() + " against " + reference.string() + ": " +
                                 e.what());
    }
}

} // namespace steerseg::kiosk
