#include "render_scene.hpp"

#include "exports/image_file.hpp"

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <sstream>

namespace steerseg::test {
using namespace steerseg::solver; // the solver under test

Volume makeScan(const Geometry& geometry, const std::function<float(glm::ivec3)>& f) {
    Volume v(VoxelType::Float32, geometry);
    auto out = v.voxels<float>();
    const glm::ivec3 d = geometry.dims;
    for (int k = 0; k < d.z; ++k) {
        for (int j = 0; j < d.y; ++j) {
            for (int i = 0; i < d.x; ++i) {
                out[v.linearIndex(i, j, k)] = f({i, j, k});
            }
        }
    }
    v.invalidateStats();
    return v;
}

Volume makeHeadScene() {
    Geometry g;
    g.dims = {48, 48, 40};
    g.spacing = {1.2, 1.2, 1.5};
    g.origin = -0.5 * g.spacing * glm::dvec3(g.dims - 1);
    return makeScan(g, [](glm::ivec3 v) {
        const glm::dvec3 p(v);
        const glm::dvec3 c(23.5, 23.5, 19.5);
        const glm::dvec3 head = (p - c) / glm::dvec3(20.0, 22.0, 17.0);
        const glm::dvec3 brain = (p - c) / glm::dvec3(17.0, 19.0, 14.0);
        float value = 20.0F;
        if (glm::dot(head, head) < 1.0) {
            value = 300.0F;
        }
        if (glm::dot(brain, brain) < 1.0) {
            value = 500.0F;
        }
        if (glm::distance(p, kHeadLesionCentre) < kHeadLesionRadius - 1.0) {
            value = 900.0F;
        }
        return value;
    });
}

PackedPool spherePool(const glm::ivec3& dims, const glm::dvec3& centre, double radius,
                      int brickSize, float phiFar) {
    const std::vector<float> phi = densePhi(dims, [&](glm::ivec3 v) {
        return static_cast<float>(glm::distance(glm::dvec3(v), centre) - radius);
    });
    return packPhi(phi, dims, brickSize, phiFar);
}

bool isYellow(const std::uint8_t* px) {
    return px[0] > 230 && px[1] > 200 && px[2] < 40;
}

bool isBlack(const std::uint8_t* px) {
    return px[0] == 0 && px[1] == 0 && px[2] == 0;
}

} // namespace steerseg::test
