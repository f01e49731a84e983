#include "kiosk/mask_dice.hpp"

#include "io/scan_reader.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

namespace steerseg::kiosk {

namespace {

std::string dimsText(const glm::ivec3& d) {
    return std::to_string(d.x) + "x" + std::to_string(d.y) + "x" + std::to_string(d.z);
}

} // namespace

double maskDice(const std::filesystem::path& mask, const std::filesystem::path& reference,
                int label) {
    const Volume a = io::readScan(mask).volume;
    const Volume b = io::readScan(reference).volume;
    if (a.dims() != b.dims()) {
        throw std::runtime_error("the mask " + mask.string() + " is " + dimsText(a.dims()) +
                                 " voxels, the reference " + reference.string() + " " +
                                 dimsText(b.dims()));
    }
    std::size_t inA = 0;
    std::size_t inB = 0;
    std::size_t both = 0;
    const std::size_t count = a.geometry().voxelCount();
    for (std::size_t n = 0; n < count; ++n) {
        const bool maskIn = a.rescale().apply(a.storedAt(n)) != 0.0;
        const double ref = b.rescale().apply(b.storedAt(n));
        const bool refIn = label < 0 ? ref != 0.0 : std::lround(ref) == label;
        inA += maskIn ? 1 : 0;
        inB += refIn ? 1 : 0;
        both += maskIn && refIn ? 1 : 0;
    }
    if (inA + inB == 0) {
        return 1.0;
    }
    return 2.0 * static_cast<double>(both) / static_cast<double>(inA + inB);
}

} // namespace steerseg::kiosk
