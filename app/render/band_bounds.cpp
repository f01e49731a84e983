#include "render/band_bounds.hpp"

#include "common/bindings.h"
#include "gpu/gl_counts.hpp"
#include "gpu/gl_error.hpp"

#include <array>
#include <cstdint>
#include <limits>

namespace steerseg::render {

namespace {

constexpr GLuint kGroupSize = 64; // band_bounds.comp's local_size_x
constexpr GLuint kMaxGroupsX = 65535;

// min = INT_MAX, max = -1: the box of no brick, what the pass's atomics start from.
constexpr std::array<std::int32_t, 6> kEmptyBox = {std::numeric_limits<std::int32_t>::max(),
                                                   std::numeric_limits<std::int32_t>::max(),
                                                   std::numeric_limits<std::int32_t>::max(),
                                                   -1,
                                                   -1,
                                                   -1};

} // namespace

BandBounds::BandBounds()
    : bounds_(gpu::createBuffer(GL_SHADER_STORAGE_BUFFER, sizeof(kEmptyBox), kEmptyBox.data(),
                                GL_DYNAMIC_DRAW)) {}

void BandBounds::update(const solver::BrickPoolView& pool) {
    const GLuint program = program_.get(&pool);
    glUseProgram(program);
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, VIEW_BAND_BOUNDS_BINDING, bounds_.id());
    glBufferSubData(GL_SHADER_STORAGE_BUFFER, 0, sizeof(kEmptyBox), kEmptyBox.data());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, PAGE_TABLE_BINDING, pool.pageTableBuffer);
    const glm::ivec3 grid = pool.brickGrid;
    glUniform3i(uniform(program, "brickGrid"), grid.x, grid.y, grid.z);
    const auto bricks =
        static_cast<GLuint>(grid.x) * static_cast<GLuint>(grid.y) * static_cast<GLuint>(grid.z);
    const GLuint groups = (bricks + kGroupSize - 1) / kGroupSize;
    if (groups == 0) {
        return; // no bricks: the box stays empty
    }
    const GLuint groupsX = groups < kMaxGroupsX ? groups : kMaxGroupsX;
    gpu::dispatchCompute(groupsX, (groups + groupsX - 1) / groupsX, 1);
    gpu::memoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
    gpu::checkGl("finding the level set's band for the 3D view");
}

} // namespace steerseg::render
