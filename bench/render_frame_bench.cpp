// Frame time of the renderer's 3D and slice views at display sizes, on the built-in sample or
// a scan file, with the level set drawn straight from the solver's brick pool: once with the
// surface still, once with one solver iteration between frames (the interactive case).
//   render_frame_bench [--scan PATH] [--scale F] [--frames N] [--size WxH] [--view NAME]
//   [--compare] [--save DIR] [--docs DIR]
// The sample's lesion is segmented from a seed at its centre (T and eps around its intensity);
// another scan gets a sphere at its centre. --scale resamples the scan (2 makes the sample
// 256x256x192) to time scan sizes no file at hand has. --size replaces the two display sizes
// (1280x800, 1920x1080) by one; --save writes the last frame of each case as PNG; --docs only
// writes the README's four 256x256 pictures and exits. --view runs one case only (3d,
// 3d+surface, ...). --compare times each 3D case also with the gradient differenced per sample
// (the ray caster before the gradient texture) in the same run, and prints the ratio.
// Besides wall time: the process's CPU time per frame (llvmpipe draws on every core, so on a
// shared machine CPU time drifts less than wall time) and rays (pixels) per second.
#include "bench/bench_scan.hpp"
#include "core/sample_phantom.hpp"
#include "platform/egl/offscreen_context.hpp"
#include "render/renderer.hpp"
#include "solver/level_set_solver.hpp"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

namespace {

using namespace steerseg;

struct Case {
    const char* name;
    render::ViewKind kind;
    bool surface;
    bool clip;
    bool stepping; // one solver iteration before each frame
};

double processCpuMs() {
    timespec ts{};
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts);
    return static_cast<double>(ts.tv_sec) * 1e3 + static_cast<double>(ts.tv_nsec) * 1e-6;
}

struct FrameTime {
    double wallMs = 0.0;
    double cpuMs = 0.0;
};

// One frame: optionally a solver iteration, then the view of the current level set.
FrameTime frameTime(render::Renderer& renderer, const render::ViewParams& p,
                    solver::LevelSetSolver* solver, bool stepping) {
    const auto start = std::chrono::steady_clock::now();
    const double cpuStart = processCpuMs();
    if (solver != nullptr && stepping) {
        solver->step(1);
    }
    const solver::BrickPoolView view =
        solver != nullptr ? solver->poolView() : solver::BrickPoolView{};
    if (solver != nullptr) {
        renderer.render(p, &view, solver->speedInputs());
    } else {
        renderer.render(p, nullptr);
    }
    glFinish();
    return {
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count(),
        processCpuMs() - cpuStart};
}

// Median wall and CPU time of `frames` frames after one warm-up (program build, first dispatch).
FrameTime medianFrame(render::Renderer& renderer, const render::ViewParams& p,
                      solver::LevelSetSolver* solver, bool stepping, int frames) {
    frameTime(renderer, p, solver, stepping);
    std::vector<double> wall;
    std::vector<double> cpu;
    for (int f = 0; f < frames; ++f) {
        const FrameTime t = frameTime(renderer, p, solver, stepping);
        wall.push_back(t.wallMs);
        cpu.push_back(t.cpuMs);
    }
    std::sort(wall.begin(), wall.end());
    std::sort(cpu.begin(), cpu.end());
    return {wall[wall.size() / 2], cpu[cpu.size() / 2]};
}

// The README's pictures: 3D with the surface, the clip plane with its yellow line, an axial
// slice with the contour, the speed function on a sagittal slice.
void writeDocImages(render::Renderer& renderer, const solver::LevelSetSolver& solver,
                    const render::SpeedParams& speed, const glm::dvec3& centre,
                    const std::filesystem::path& dir) {
    std::filesystem::create_directories(dir);
    const solver::BrickPoolView view = solver.poolView();
    const glm::ivec2 size{256, 256};
    render::ViewParams p = renderer.defaultParams(render::ViewKind::Volume3d, size);
    p.camera.orbit(25.0, 15.0);
    p.surface = render::SurfaceMode::Opaque;
    p.speed = speed;
    renderer.render(p, &view, solver.speedInputs());
    bench::saveImage(dir / "render_3d_surface.png", renderer.readback());
    p.clip = {true, {0.0, -1.0, 0.0}, -centre.y};
    renderer.render(p, &view, solver.speedInputs());
    bench::saveImage(dir / "render_3d_clip.png", renderer.readback());
    p = renderer.defaultParams(render::ViewKind::Axial, size);
    p.slice = static_cast<int>(centre.z);
    renderer.render(p, &view);
    bench::saveImage(dir / "render_axial_contour.png", renderer.readback());
    p = renderer.defaultParams(render::ViewKind::Sagittal, size);
    p.slice = static_cast<int>(centre.x);
    p.content = render::SliceContent::Speed;
    p.speed = {kPhantomLesion.intensity, 60.0};
    renderer.render(p, &view);
    bench::saveImage(dir / "render_sagittal_speed.png", renderer.readback());
}

} // namespace

int main(int argc, char** argv) {
    const std::string builtin = "builtin:sample";
    std::string scanPath = builtin;
    double scale = 1.0;
    int frames = 3;
    std::vector<glm::ivec2> sizes = {{1280, 800}, {1920, 1080}};
    std::filesystem::path saveDir;
    std::filesystem::path docsDir;
    std::string only;
    bool compare = false;
    for (int n = 1; n < argc; n += 2) {
        const std::string key = argv[n];
        if (key == "--compare") {
            compare = true;
            --n;
            continue;
        }
        if (n + 1 >= argc) {
            std::fprintf(stderr, "render_frame_bench: %s needs a value\n", key.c_str());
            return 2;
        }
        if (key == "--view") {
            only = argv[n + 1];
        } else if (key == "--scan") {
            scanPath = argv[n + 1];
        } else if (key == "--scale") {
            scale = std::atof(argv[n + 1]);
        } else if (key == "--frames") {
            frames = std::clamp(std::atoi(argv[n + 1]), 1, 1000);
        } else if (key == "--size") {
            int w = 0;
            int h = 0;
            if (std::sscanf(argv[n + 1], "%dx%d", &w, &h) != 2 || w < 1 || h < 1 || w > 8192 ||
                h > 8192) {
                std::fprintf(stderr, "render_frame_bench: --size expects WxH\n");
                return 2;
            }
            sizes = {{w, h}};
        } else if (key == "--save") {
            saveDir = argv[n + 1];
        } else if (key == "--docs") {
            docsDir = argv[n + 1];
        } else {
            std::fprintf(stderr, "usage: render_frame_bench [--scan PATH] [--scale F] [--frames N] "
                                 "[--size WxH] [--view NAME] [--compare] [--save DIR] "
                                 "[--docs DIR]\n");
            return 2;
        }
    }
    try {
        Volume volume = bench::loadScan(scanPath);
        if (scale != 1.0) {
            volume = bench::resampled(volume, scale);
        }
        const Geometry& g = volume.geometry();
        auto context = platform::createOffscreenContext();
        std::printf("GL_RENDERER: %s\nscan: %s %dx%dx%d\n",
                    reinterpret_cast<const char*>(glGetString(GL_RENDERER)), scanPath.c_str(),
                    g.dims.x, g.dims.y, g.dims.z);
        solver::LevelSetSolver solver(volume);
        render::Renderer renderer(volume, solver.scan());
        std::unique_ptr<render::Renderer> differencing;
        if (compare) {
            differencing = std::make_unique<render::Renderer>(volume, solver.scan(), 0);
        }
        std::printf("gradient texture: %s\n", renderer.precomputedGradient() ? "yes" : "no");
        glm::dvec3 centre = 0.5 * glm::dvec3(g.dims - 1);
        render::SpeedParams speed; // the solver's, as the kiosk's 3D view gets them
        if (scanPath == builtin) {
            centre = glm::dvec3(kPhantomLesion.i, kPhantomLesion.j, kPhantomLesion.k) *
                     (glm::dvec3(g.dims - 1) / glm::dvec3(127, 127, 95));
            solver.addSphere({glm::vec3(centre), 5.0F * static_cast<float>(scale)});
            speed = {kPhantomLesion.intensity, 100.0, true};
            solver.setParams({static_cast<float>(speed.T), static_cast<float>(speed.eps), 0.8F});
            const model::StepResult r = solver.runUntilConverged(2000);
            std::size_t inside = 0;
            for (const std::uint8_t m : solver.readMask()) {
                inside += m;
            }
            // The same numbers on every driver, or the driver computes something else.
            std::printf("lesion: %d iterations, evolved time %.4f, %zu voxels inside%s\n",
                        r.iterations, static_cast<double>(r.evolvedTime), inside,
                        r.converged ? ", converged" : ", NOT converged");
        } else {
            const float r = 0.15F * static_cast<float>(std::min({g.dims.x, g.dims.y, g.dims.z}));
            solver.addSphere({glm::vec3(centre), r});
            const IntensityStats& st = volume.stats();
            speed = {st.mean, st.max - st.min, true};
            solver.setParams({static_cast<float>(speed.T), static_cast<float>(speed.eps), 0.5F});
        }

        if (!docsDir.empty()) {
            writeDocImages(renderer, solver, speed, centre, docsDir);
            return 0;
        }
        const Case cases[] = {
            {"3d", render::ViewKind::Volume3d, false, false, false},
            {"3d+surface", render::ViewKind::Volume3d, true, false, false},
            {"3d+surface+clip", render::ViewKind::Volume3d, true, true, false},
            {"3d+surface+solver", render::ViewKind::Volume3d, true, false, true},
            {"axial+contour", render::ViewKind::Axial, true, false, false},
            {"axial+solver", render::ViewKind::Axial, true, false, true},
        };
        std::setvbuf(stdout, nullptr, _IOLBF, 0); // progress shows while slow cases run
        std::printf("%-18s %-10s %10s %10s %8s %8s%s\n", "view", "size", "median ms", "cpu ms",
                    "fps", "Mrays/s", compare ? "   before cpu ms  ratio" : "");
        for (const glm::ivec2& size : sizes) {
            for (const Case& c : cases) {
                if (!only.empty() && only != c.name) {
                    continue;
                }
                render::ViewParams p = renderer.defaultParams(c.kind, size);
                p.slice = static_cast<int>(centre.z);
                p.camera.orbit(20.0, 15.0);
                if (c.clip) {
                    p.clip = {true, {0.0, -1.0, 0.0}, -centre.y};
                }
                if (c.surface) {
                    p.speed = speed;
                }
                solver::LevelSetSolver* s = c.surface ? &solver : nullptr;
                const FrameTime t = medianFrame(renderer, p, s, c.stepping, frames);
                const double rays = static_cast<double>(size.x) * size.y;
                std::printf("%-18s %4dx%-5d %10.1f %10.1f %8.2f %8.2f", c.name, size.x, size.y,
                            t.wallMs, t.cpuMs, 1000.0 / t.wallMs, rays / (t.wallMs * 1e3));
                if (differencing && c.kind == render::ViewKind::Volume3d) {
                    const FrameTime b = medianFrame(*differencing, p, s, c.stepping, frames);
                    std::printf(" %16.1f %6.2f", b.cpuMs, b.cpuMs / t.cpuMs);
                }
                std::printf("\n");
                if (!saveDir.empty()) {
                    std::filesystem::create_directories(saveDir);
                    bench::saveImage(
                        saveDir / (std::string(c.name) + "_" + std::to_string(size.x) + ".png"),
                        renderer.readback());
                }
            }
        }
        return 0;
    } catch (const std::exception& e) {
        std::fprintf(stderr, "render_frame_bench: %s\n", e.what());
        return 1;
    }
}
