#include "render/structure_labels.hpp"

#include "gpu/gl_error.hpp"
#include "render/render_bindings.h"
#include "render/skip_grid.hpp"

#include <algorithm>
#include <stdexcept>
#include <string>

namespace steerseg::render {

static_assert(kMaxStructureSurfaces == VIEW_MAX_STRUCTURE_LABELS);
static_assert(kMaxStructureSurfaces < 256, "labels are one byte");

namespace {

// Writes `label` over the voxels of `runs` that no earlier layer holds.
void paintRuns(const MaskRuns& runs, std::uint8_t label, std::vector<std::uint8_t>& labels) {
    std::size_t at = 0;
    for (std::size_t n = 0; n < runs.runs.size(); ++n) {
        const std::size_t length = runs.runs[n];
        if (length > labels.size() - at) {
            throw std::invalid_argument("a structure's runs hold more voxels than the scan");
        }
        if (n % 2 == 1) {
            const auto first = labels.begin() + static_cast<std::ptrdiff_t>(at);
            std::replace(first, first + static_cast<std::ptrdiff_t>(length), std::uint8_t{0},
                         label);
        }
        at += length;
    }
    if (at != labels.size()) {
        throw std::invalid_argument("a structure's runs hold fewer voxels than the scan");
    }
}

} // namespace

StructureLabels::StructureLabels(const glm::ivec3& dims, int block) : dims_(dims), block_(block) {}

void StructureLabels::boxOfBlocks() {
    const glm::ivec3 grid = (dims_ + block_ - 1) / block_;
    boxLo_ = grid;
    boxHi_ = glm::ivec3(-1);
    std::size_t b = 0;
    for (int z = 0; z < grid.z && !blocks_.empty(); ++z) {
        for (int y = 0; y < grid.y; ++y) {
            for (int x = 0; x < grid.x; ++x, ++b) {
                if (blocks_[b] != 0) {
                    boxLo_ = glm::min(boxLo_, glm::ivec3(x, y, z));
                    boxHi_ = glm::max(boxHi_, glm::ivec3(x, y, z));
                }
            }
        }
    }
}

bool StructureLabels::set(std::span<const StructureSurface> layers, std::uint64_t version) {
    if (version_ == version) {
        return false;
    }
    const std::size_t voxels = static_cast<std::size_t>(dims_.x) *
                               static_cast<std::size_t>(dims_.y) *
                               static_cast<std::size_t>(dims_.z);
    std::vector<const StructureSurface*> shown;
    for (const StructureSurface& layer : layers) {
        if (layer.mask == nullptr) {
            throw std::invalid_argument("a structure layer without a mask");
        }
        if (!layer.visible || layer.mask->runs.empty()) {
            continue;
        }
        if (layer.mask->voxels != voxels) {
            throw std::invalid_argument("a structure's mask holds " +
                                        std::to_string(layer.mask->voxels) + " voxels, the scan " +
                                        std::to_string(voxels));
        }
        shown.push_back(&layer);
    }
    if (shown.size() > kMaxStructureSurfaces) {
        throw std::invalid_argument(std::to_string(shown.size()) + " structures shown, at most " +
                                    std::to_string(kMaxStructureSurfaces));
    }
    std::vector<glm::vec3> colours;
    std::vector<std::uint8_t> blocks;
    if (!shown.empty()) {
        std::vector<std::uint8_t> labels(voxels, 0);
        for (std::size_t n = 0; n < shown.size(); ++n) {
            paintRuns(*shown[n]->mask, static_cast<std::uint8_t>(n + 1), labels);
            colours.push_back(glm::clamp(shown[n]->colour, glm::vec3(0.0F), glm::vec3(1.0F)));
        }
        blocks = labelledBlocks(labels, dims_, block_);
        if (!texture_) {
            texture_ = gpu::createTexture();
            glBindTexture(GL_TEXTURE_3D, texture_.id());
            glTexStorage3D(GL_TEXTURE_3D, 1, GL_R8UI, dims_.x, dims_.y, dims_.z);
            // An integer texture is incomplete, and reads as 0, under linear filtering.
            glTexParameteri(GL_TEXTURE_3D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
            glTexParameteri(GL_TEXTURE_3D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
        }
        glBindTexture(GL_TEXTURE_3D, texture_.id());
        glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
        glBindBuffer(GL_PIXEL_UNPACK_BUFFER, 0);
        glTexSubImage3D(GL_TEXTURE_3D, 0, 0, 0, 0, dims_.x, dims_.y, dims_.z, GL_RED_INTEGER,
                        GL_UNSIGNED_BYTE, labels.data());
        gpu::checkGl("uploading the structures' labels");
    } else {
        texture_.reset(); // nothing shown: no scan-sized texture held for it
    }
    colours_ = std::move(colours);
    blocks_ = std::move(blocks);
    boxOfBlocks();
    version_ = version;
    ++uploads_;
    return true;
}

} // namespace steerseg::render
