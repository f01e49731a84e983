#include "render_scene.hpp"

#include "io/image_file.hpp"

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <sstream>

namespace steerseg::test {

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

GoldenResult compareGolden(const std::string& name, const RgbaImage& actual, int pixelTolerance,
                           double maxDifferingFraction) {
    // Compiled in (tests/gpu/CMakeLists.txt) so the check never depends on the environment.
    const std::filesystem::path goldenDir = STEERSEG_GOLDEN_DIR;
    const std::filesystem::path golden = goldenDir / (name + ".png");
    const char* update = std::getenv("STEERSEG_UPDATE_GOLDEN");
    if (update != nullptr && std::string(update) == "1") {
        std::filesystem::create_directories(goldenDir);
        io::writeImage(golden, actual);
        return {true, "rewrote " + golden.string()};
    }
    const std::filesystem::path here =
        std::filesystem::read_symlink("/proc/self/exe").parent_path(); // beside the binary
    const std::filesystem::path actualPath = here / (name + ".actual.png");
    const std::filesystem::path diffPath = here / (name + ".diff.png");
    if (!std::filesystem::exists(golden)) {
        io::writeImage(actualPath, actual);
        return {false, "no golden " + golden.string() + " (actual written to " +
                           actualPath.string() + "; set STEERSEG_UPDATE_GOLDEN=1 to create it)"};
    }
    const RgbaImage expected = io::readImage(golden);
    if (expected.width != actual.width || expected.height != actual.height) {
        io::writeImage(actualPath, actual);
        return {false, "size differs from " + golden.string() + "; actual: " + actualPath.string()};
    }
    RgbaImage diff{actual.width, actual.height, {}};
    diff.pixels.assign(actual.pixels.size(), 0);
    std::size_t differing = 0;
    int worst = 0;
    for (int y = 0; y < actual.height; ++y) {
        for (int x = 0; x < actual.width; ++x) {
            int d = 0;
            for (int c = 0; c < 3; ++c) {
                d = std::max(d, std::abs(int(actual.at(x, y)[c]) - int(expected.at(x, y)[c])));
            }
            worst = std::max(worst, d);
            std::uint8_t* out = diff.at(x, y);
            out[0] = static_cast<std::uint8_t>(std::min(255, d * 4));
            out[1] = d > pixelTolerance ? 255 : 0;
            out[2] = 0;
            out[3] = 255;
            if (d > pixelTolerance) {
                ++differing;
            }
        }
    }
    const double fraction =
        static_cast<double>(differing) / static_cast<double>(actual.width * actual.height);
    if (fraction <= maxDifferingFraction) {
        return {true, ""};
    }
    io::writeImage(actualPath, actual);
    io::writeImage(diffPath, diff);
    std::ostringstream msg;
    msg << name << ": " << differing << " pixels (" << fraction * 100.0 << "%) differ by more than "
        << pixelTolerance << " (worst " << worst << "); actual: " << actualPath.string()
        << ", diff: " << diffPath.string() << " (STEERSEG_UPDATE_GOLDEN=1 rewrites the golden)";
    return {false, msg.str()};
}

} // namespace steerseg::test
