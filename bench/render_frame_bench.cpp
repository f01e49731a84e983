// Frame time of the renderer's 3D and slice views at display sizes, on the built-in sample or
// a scan file, with the level set drawn from a brick pool. Until the solver lands the pool is
// the phantom lesion's analytic sphere packed by the test-only packer (tests/support), so
// "with solver steps" is not measured here yet.
//   render_frame_bench [--scan PATH] [--frames N] [--save DIR] [--docs DIR]
// --save writes the last frame of each case as PNG; --docs only writes the README's four
// 256x256 pictures of the scan and its sphere and exits.
#include "core/sample_phantom.hpp"
#include "io/scan_reader.hpp"
#include "platform/egl/gpu_context.hpp"
#include "render/renderer.hpp"
#include "support/pool_packer.hpp"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <vector>

namespace {

using namespace steerseg;

struct Case {
    const char* name;
    render::ViewKind kind;
    glm::ivec2 size;
    bool surface;
    bool clip;
};

double frameMs(render::Renderer& renderer, const render::ViewParams& p, const BrickPoolView* pool) {
    const auto start = std::chrono::steady_clock::now();
    renderer.render(p, pool);
    glFinish();
    return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start)
        .count();
}

// The README's pictures: 3D with the surface, the clip plane with its yellow line, an axial
// slice with the contour, the speed function on a sagittal slice.
void writeDocImages(render::Renderer& renderer, const BrickPoolView& view, const glm::dvec3& centre,
                    const std::filesystem::path& dir) {
    std::filesystem::create_directories(dir);
    const glm::ivec2 size{256, 256};
    render::ViewParams p = renderer.defaultParams(render::ViewKind::Volume3d, size);
    p.camera.orbit(25.0, 15.0);
    p.surface = render::SurfaceMode::Opaque;
    renderer.render(p, &view);
    render::writeImage(dir / "render_3d_surface.png", renderer.readback());
    p.clip = {true, {0.0, -1.0, 0.0}, -centre.y};
    renderer.render(p, &view);
    render::writeImage(dir / "render_3d_clip.png", renderer.readback());
    p = renderer.defaultParams(render::ViewKind::Axial, size);
    p.slice = static_cast<int>(centre.z);
    renderer.render(p, &view);
    render::writeImage(dir / "render_axial_contour.png", renderer.readback());
    p = renderer.defaultParams(render::ViewKind::Sagittal, size);
    p.slice = static_cast<int>(centre.x);
    p.content = render::SliceContent::Speed;
    p.speed = {kPhantomLesion.intensity, 60.0};
    renderer.render(p, &view);
    render::writeImage(dir / "render_sagittal_speed.png", renderer.readback());
}

} // namespace

int main(int argc, char** argv) {
    std::string scanPath = io::kBuiltinSample;
    int frames = 3;
    std::filesystem::path saveDir;
    std::filesystem::path docsDir;
    for (int n = 1; n + 1 < argc; n += 2) {
        const std::string key = argv[n];
        if (key == "--scan") {
            scanPath = argv[n + 1];
        } else if (key == "--frames") {
            frames = std::clamp(std::atoi(argv[n + 1]), 1, 1000);
        } else if (key == "--save") {
            saveDir = argv[n + 1];
        } else if (key == "--docs") {
            docsDir = argv[n + 1];
        } else {
            std::fprintf(
                stderr,
                "usage: render_frame_bench [--scan PATH] [--frames N] [--save DIR] [--docs DIR]\n");
            return 2;
        }
    }
    try {
        const io::LoadedScan scan = io::readScan(scanPath);
        const Geometry& g = scan.volume.geometry();
        auto context = platform::createOffscreenContext();
        std::printf("GL_RENDERER: %s\nscan: %s %dx%dx%d\n",
                    reinterpret_cast<const char*>(glGetString(GL_RENDERER)), scanPath.c_str(),
                    g.dims.x, g.dims.y, g.dims.z);
        render::Renderer renderer(scan.volume);
        // A sphere around the sample's lesion (or the volume's centre for another scan).
        glm::dvec3 centre = 0.5 * glm::dvec3(g.dims - 1);
        double radius = 0.15 * std::min({g.dims.x, g.dims.y, g.dims.z});
        if (scanPath == io::kBuiltinSample) {
            centre = {kPhantomLesion.i, kPhantomLesion.j, kPhantomLesion.k};
            radius = kPhantomLesion.radiusMm / std::min({g.spacing.x, g.spacing.y, g.spacing.z});
        }
        // Round in millimetres, phi in units of the smallest spacing.
        const double unit = std::min({g.spacing.x, g.spacing.y, g.spacing.z});
        const std::vector<float> phi = test::densePhi(g.dims, [&](glm::ivec3 v) {
            const double mm = glm::length((glm::dvec3(v) - centre) * g.spacing);
            return static_cast<float>(mm / unit - radius);
        });
        test::GpuPool pool(test::packPhi(phi, g.dims, 8, 4.0F));
        const BrickPoolView view = pool.view();

        if (!docsDir.empty()) {
            writeDocImages(renderer, view, centre, docsDir);
            return 0;
        }
        const Case cases[] = {
            {"3d", render::ViewKind::Volume3d, {1280, 800}, false, false},
            {"3d+surface", render::ViewKind::Volume3d, {1280, 800}, true, false},
            {"3d+surface+clip", render::ViewKind::Volume3d, {1280, 800}, true, true},
            {"axial+contour", render::ViewKind::Axial, {1280, 800}, true, false},
            {"3d", render::ViewKind::Volume3d, {1920, 1080}, false, false},
            {"3d+surface", render::ViewKind::Volume3d, {1920, 1080}, true, false},
            {"3d+surface+clip", render::ViewKind::Volume3d, {1920, 1080}, true, true},
            {"axial+contour", render::ViewKind::Axial, {1920, 1080}, true, false},
        };
        std::setvbuf(stdout, nullptr, _IOLBF, 0); // progress shows while slow cases run
        std::printf("%-18s %-10s %10s %10s %8s\n", "view", "size", "min ms", "median ms", "fps");
        for (const Case& c : cases) {
            render::ViewParams p = renderer.defaultParams(c.kind, c.size);
            p.slice = static_cast<int>(centre.z);
            p.camera.orbit(20.0, 15.0);
            if (c.clip) {
                p.clip = {true, {0.0, -1.0, 0.0}, -centre.y};
            }
            const BrickPoolView* pv = c.surface ? &view : nullptr;
            frameMs(renderer, p, pv); // warm-up: program build, first dispatch
            std::vector<double> times;
            for (int f = 0; f < frames; ++f) {
                times.push_back(frameMs(renderer, p, pv));
            }
            std::sort(times.begin(), times.end());
            const double median = times[times.size() / 2];
            std::printf("%-18s %4dx%-5d %10.1f %10.1f %8.1f\n", c.name, c.size.x, c.size.y,
                        times.front(), median, 1000.0 / median);
            if (!saveDir.empty()) {
                std::filesystem::create_directories(saveDir);
                render::writeImage(
                    saveDir / (std::string(c.name) + "_" + std::to_string(c.size.x) + ".png"),
                    renderer.readback());
            }
        }
        return 0;
    } catch (const std::exception& e) {
        std::fprintf(stderr, "render_frame_bench: %s\n", e.what());
        return 1;
    }
}
