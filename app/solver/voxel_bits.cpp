#include "solver/voxel_bits.hpp"

#include "gpu/gl_error.hpp"

#include <algorithm>
#include <stdexcept>
#include <string>
#include <vector>

namespace steerseg::solver::detail {

gpu::Texture uploadVoxelBits(std::span<const std::uint8_t> mask, const glm::ivec3& dims, int unit,
                             const char* what) {
    const std::size_t voxels = static_cast<std::size_t>(dims.x) * static_cast<std::size_t>(dims.y) *
                               static_cast<std::size_t>(dims.z);
    if (!mask.empty() && mask.size() != voxels) {
        throw std::invalid_argument(std::string(what) + " mask has " + std::to_string(mask.size()) +
                                    " voxels but the scan " + std::to_string(voxels));
    }
    if (std::none_of(mask.begin(), mask.end(), [](std::uint8_t v) { return v != 0; })) {
        return {};
    }
    const glm::ivec3 packed((dims.x + 31) / 32, dims.y, dims.z);
    std::vector<std::uint32_t> bits(static_cast<std::size_t>(packed.x) *
                                    static_cast<std::size_t>(packed.y) *
                                    static_cast<std::size_t>(packed.z));
    std::size_t v = 0;
    for (std::size_t row = 0; row < voxels / static_cast<std::size_t>(dims.x); ++row) {
        std::uint32_t* words = bits.data() + row * static_cast<std::size_t>(packed.x);
        for (int i = 0; i < dims.x; ++i, ++v) {
            if (mask[v] != 0) {
                words[i / 32] |= 1U << (i % 32);
            }
        }
    }
    gpu::Texture texture = gpu::createTexture();
    glActiveTexture(static_cast<GLenum>(GL_TEXTURE0 + unit));
    glBindTexture(GL_TEXTURE_3D, texture.id());
    glTexStorage3D(GL_TEXTURE_3D, 1, GL_R32UI, packed.x, packed.y, packed.z);
    // An integer texture filtered other than NEAREST is incomplete, even for texelFetch.
    glTexParameteri(GL_TEXTURE_3D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_3D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glBindBuffer(GL_PIXEL_UNPACK_BUFFER, 0);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
    glTexSubImage3D(GL_TEXTURE_3D, 0, 0, 0, 0, packed.x, packed.y, packed.z, GL_RED_INTEGER,
                    GL_UNSIGNED_INT, bits.data());
    gpu::checkGl((std::string("uploading the ") + what + " voxels").c_str());
    return texture;
}

} // namespace steerseg::solver::detail
