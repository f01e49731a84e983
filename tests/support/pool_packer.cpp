#include "support/pool_packer.hpp"

#include <algorithm>

namespace steerseg::test {
using namespace steerseg::solver; // the solver under test

namespace {

std::size_t linear(const glm::ivec3& dims, const glm::ivec3& v) {
    return static_cast<std::size_t>(v.x) +
           static_cast<std::size_t>(dims.x) *
               (static_cast<std::size_t>(v.y) +
                static_cast<std::size_t>(dims.y) * static_cast<std::size_t>(v.z));
}

} // namespace

std::vector<float> densePhi(const glm::ivec3& dims, const std::function<float(glm::ivec3)>& f) {
    std::vector<float> phi(static_cast<std::size_t>(dims.x) * dims.y * dims.z);
    for (int k = 0; k < dims.z; ++k) {
        for (int j = 0; j < dims.y; ++j) {
            for (int i = 0; i < dims.x; ++i) {
                phi[linear(dims, {i, j, k})] = f({i, j, k});
            }
        }
    }
    return phi;
}

PackedPool packPhi(const std::vector<float>& phi, const glm::ivec3& dims, int brickSize,
                   float phiFar) {
    PackedPool p;
    p.dims = dims;
    p.brickSize = brickSize;
    p.phiFar = phiFar;
    p.brickGrid = (dims + brickSize - 1) / brickSize;
    const auto brickVoxels = static_cast<std::size_t>(brickSize * brickSize * brickSize);
    p.pageTable.assign(static_cast<std::size_t>(p.brickGrid.x) * p.brickGrid.y * p.brickGrid.z,
                       kBrickOutside);
    std::vector<float> local(brickVoxels);
    for (int bz = 0; bz < p.brickGrid.z; ++bz) {
        for (int by = 0; by < p.brickGrid.y; ++by) {
            for (int bx = 0; bx < p.brickGrid.x; ++bx) {
                bool allInside = true;
                bool allOutside = true;
                for (int lz = 0; lz < brickSize; ++lz) {
                    for (int ly = 0; ly < brickSize; ++ly) {
                        for (int lx = 0; lx < brickSize; ++lx) {
                            // Voxels past the volume's end repeat the border (never read).
                            const glm::ivec3 v = glm::min(glm::ivec3(bx, by, bz) * brickSize +
                                                              glm::ivec3(lx, ly, lz),
                                                          dims - 1);
                            const float value = std::clamp(phi[linear(dims, v)], -phiFar, phiFar);
                            local[static_cast<std::size_t>(lx + brickSize *
                                                                    (ly + brickSize * lz))] = value;
                            allInside = allInside && value <= -phiFar;
                            allOutside = allOutside && value >= phiFar;
                        }
                    }
                }
                const std::size_t brick = linear(p.brickGrid, {bx, by, bz});
                if (allInside) {
                    p.pageTable[brick] = kBrickInside;
                } else if (allOutside) {
                    p.pageTable[brick] = kBrickOutside;
                } else {
                    p.pageTable[brick] = static_cast<std::uint32_t>(p.pool.size() / brickVoxels);
                    p.pool.insert(p.pool.end(), local.begin(), local.end());
                }
            }
        }
    }
    return p;
}

GpuPool::GpuPool(const PackedPool& packed) {
    pageTable_ =
        gpu::createBuffer(GL_SHADER_STORAGE_BUFFER,
                          static_cast<GLsizeiptr>(packed.pageTable.size() * sizeof(std::uint32_t)),
                          packed.pageTable.data(), GL_STATIC_DRAW);
    // At least one float so the binding is valid when every brick is constant.
    std::vector<float> pool = packed.pool;
    if (pool.empty()) {
        pool.push_back(0.0F);
    }
    pool_ = gpu::createBuffer(GL_SHADER_STORAGE_BUFFER,
                              static_cast<GLsizeiptr>(pool.size() * sizeof(float)), pool.data(),
                              GL_STATIC_DRAW);
    pooledBricks_ =
        packed.pool.size() /
        static_cast<std::size_t>(packed.brickSize * packed.brickSize * packed.brickSize);
    view_.pageTableBuffer = pageTable_.id();
    view_.phiPoolBuffer = pool_.id();
    view_.volumeDims = packed.dims;
    view_.brickGrid = packed.brickGrid;
    view_.brickSize = packed.brickSize;
    view_.phiFar = packed.phiFar;
}

BrickPoolView GpuPool::view() const {
    return view_;
}

} // namespace steerseg::test
