#include "core/mask_overlap.hpp"

#include "core/mask_inside.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

namespace steerseg {

namespace {

bool inReference(const Volume& reference, std::size_t n, int label) {
    const double ref = reference.rescale().apply(reference.storedAt(n));
    return label < 0 ? insideValue(ref) : std::lround(ref) == label;
}

template <typename InsideAt>
MaskOverlap countOverlap(std::size_t count, InsideAt insideAt, const Volume& reference, int label) {
    MaskOverlap o;
    for (std::size_t n = 0; n < count; ++n) {
        const bool maskIn = insideAt(n);
        const bool refIn = inReference(reference, n, label);
        o.mask += maskIn ? 1 : 0;
        o.reference += refIn ? 1 : 0;
        o.both += maskIn && refIn ? 1 : 0;
    }
    return o;
}

} // namespace

MaskOverlap maskOverlap(std::span<const std::uint8_t> mask, const Volume& reference, int label) {
    if (mask.size() != reference.geometry().voxelCount()) {
        throw std::invalid_argument("the mask has " + std::to_string(mask.size()) +
                                    " voxels, the reference " + dimsText(reference.dims()) + " = " +
                                    std::to_string(reference.geometry().voxelCount()));
    }
    return countOverlap(
        mask.size(), [&](std::size_t n) { return mask[n] != 0; }, reference, label);
}

MaskOverlap maskOverlap(const Volume& mask, const Volume& reference, int label) {
    if (mask.dims() != reference.dims()) {
        throw std::invalid_argument("the mask is " + dimsText(mask.dims()) +
                                    " voxels, the reference " + dimsText(reference.dims()));
    }
    return maskOverlap(maskInside(mask), reference, label);
}

std::vector<std::uint8_t> referenceVoxels(const Volume& reference, int label) {
    std::vector<std::uint8_t> out(reference.geometry().voxelCount());
    for (std::size_t n = 0; n < out.size(); ++n) {
        out[n] = inReference(reference, n, label) ? 1 : 0;
    }
    return out;
}

std::size_t differencesOffSurface(const glm::ivec3& dims, std::span<const std::uint8_t> a,
                                  std::span<const std::uint8_t> reference) {
    static constexpr glm::ivec3 kFaces[6] = {{1, 0, 0},  {-1, 0, 0}, {0, 1, 0},
                                             {0, -1, 0}, {0, 0, 1},  {0, 0, -1}};
    std::size_t off = 0;
    std::size_t n = 0;
    for (int k = 0; k < dims.z; ++k) {
        for (int j = 0; j < dims.y; ++j) {
            for (int i = 0; i < dims.x; ++i, ++n) {
                if (a[n] == reference[n]) {
                    continue;
                }
                bool surface = false;
                for (const glm::ivec3 f : kFaces) {
                    const glm::ivec3 p = glm::ivec3(i, j, k) + f;
                    surface =
                        surface || (glm::all(glm::greaterThanEqual(p, glm::ivec3(0))) &&
                                    glm::all(glm::lessThan(p, dims)) &&
                                    reference[linearIndex(dims, p.x, p.y, p.z)] != reference[n]);
                }
                off += surface ? 0 : 1;
            }
        }
    }
    return off;
}

} // namespace steerseg
