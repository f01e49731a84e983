#pragma once

#include "gpu/gl_handle.hpp"
#include "render/structure_surface.hpp"

#include <cstdint>
#include <glm/glm.hpp>
#include <optional>
#include <span>
#include <vector>

namespace steerseg::render {

// The other structures on the GPU for the 3D view: one R8UI texture of the scan's size, 0 where
// no shown structure lies, n where the n-th shown one does (the first of the list where they
// overlap), their colours, and which skipping blocks hold a label. Painted from the runs into
// one byte per voxel, uploaded only when the list's version changes. Needs a current GLES 3.1
// context; the caller saves the GL state.
class StructureLabels {
  public:
    // `block`: the skipping grid's block size (SkipGrid::blockSize()).
    StructureLabels(const glm::ivec3& dims, int block);

    // The visible layers with a surface, uploaded when `version` differs from the last one
    // given (always the first time). Returns whether it uploaded. std::invalid_argument for a
    // layer without a mask, one of another size or with runs that do not add up, or more than
    // kMaxStructureSurfaces shown; the labels are then as they were.
    bool set(std::span<const StructureSurface> layers, std::uint64_t version);

    [[nodiscard]] std::optional<std::uint64_t> version() const { return version_; }
    // No structure to draw: the ray caster runs without their code.
    [[nodiscard]] bool empty() const { return colours_.empty(); }
    [[nodiscard]] GLuint texture() const { return texture_.id(); }
    // The colour of label n + 1.
    [[nodiscard]] const std::vector<glm::vec3>& colours() const { return colours_; }
    // Per skipping block (x fastest): 1 where a label lies (labelledBlocks()); empty when
    // empty(). The box of those blocks (inclusive), for rays that miss it to search no further.
    [[nodiscard]] const std::vector<std::uint8_t>& blocks() const { return blocks_; }
    [[nodiscard]] glm::ivec3 blockBoxLo() const { return boxLo_; }
    [[nodiscard]] glm::ivec3 blockBoxHi() const { return boxHi_; }
    // How many times set() uploaded: the 3D view merges the blocks again when it moves.
    [[nodiscard]] std::uint64_t uploads() const { return uploads_; }

  private:
    void boxOfBlocks();

    glm::ivec3 dims_;
    int block_;
    std::optional<std::uint64_t> version_;
    std::uint64_t uploads_ = 0;
    gpu::Texture texture_;
    std::vector<glm::vec3> colours_;
    std::vector<std::uint8_t> blocks_;
    glm::ivec3 boxLo_{0};
    glm::ivec3 boxHi_{-1};
};

} // namespace steerseg::render
