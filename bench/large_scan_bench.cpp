// A scan of the size a modern CT scanner writes, end to end: a synthetic int16 CT series
// (512x512x1000 by default, 500 MiB of voxels, one DICOM file per slice) is written, read back
// by steerseg's DICOM reader and by ITK's (steerseg-itk-dicom-read: GDCMSeriesFileNames +
// ImageSeriesReader + GDCMImageIO), each in a child process of its own, alternately, --repeat
// times (wall time and peak host memory above the child's start, against the voxel bytes),
// then uploaded to the GPU, segmented from a seed in its lesion (iterations/s, active bricks,
// pool memory, the lesion's size against the truth), drawn once in 3D, and a large front (a
// sphere in the body, the surface of a large organ) stepped --body-iterations times for the
// solver's rate and pool at a realistic active set.
//   large_scan_bench [--size WxHxD] [--dir DIR] [--keep] [--frame WxH] [--repeat N]
//                    [--body-iterations N] [--itk PATH | --no-itk] [--load-only] [--json FILE]
// --dir writes the series there (default: a temporary folder, removed at the end unless --keep).
// --itk: the ITK reader (default: steerseg-itk-dicom-read beside this binary, built with
// -DSTEERSEG_BENCH_ITK=ON; without it the ITK column is skipped, and the output says so).
#include "bench/large_scan/synthetic_ct.hpp"
#include "bench/proc_status.hpp"
#include "gpu/gl.hpp"
#include "gpu/scan_texture.hpp"
#include "platform/egl/offscreen_context.hpp"
#include "render/renderer.hpp"
#include "scan/scan_reader.hpp"
#include "solver/level_set_solver.hpp"

#include <algorithm>
#include <array>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <sys/wait.h>
#include <unistd.h>

namespace {

using namespace steerseg;
using Clock = std::chrono::steady_clock;

double secondsSince(Clock::time_point start) {
    return std::chrono::duration<double>(Clock::now() - start).count();
}

struct LoadFigures {
    double seconds = 0.0;
    double peakBytes = 0.0; // above the child's resident size at its start
    double sum = 0.0;       // of the voxels in real units (both readers must agree)
};

// Reads the series in a child process, so that its peak memory is the reader's alone.
LoadFigures loadInChild(const std::filesystem::path& dir) {
    int fds[2];
    if (pipe(fds) != 0) {
        throw std::runtime_error("pipe failed");
    }
    const pid_t pid = fork();
    if (pid == 0) {
        close(fds[0]);
        LoadFigures f;
        const double before = bench::statusBytes("VmRSS");
        const auto start = Clock::now();
        try {
            const scan::LoadedScan scan = scan::readScan(dir);
            f.seconds = secondsSince(start);
            f.peakBytes = bench::statusBytes("VmHWM") - before;
            const Volume& v = scan.volume;
            const std::size_t slice =
                static_cast<std::size_t>(v.dims().x) * static_cast<std::size_t>(v.dims().y);
            std::vector<float> values(slice);
            for (int k = 0; k < v.dims().z; ++k) {
                v.realValues(slice * static_cast<std::size_t>(k), values);
                for (const float x : values) {
                    f.sum += static_cast<double>(x);
                }
            }
        } catch (const std::exception& e) {
            std::fprintf(stderr, "large_scan_bench: loading in the child: %s\n", e.what());
            _exit(1);
        }
        const ssize_t n = write(fds[1], &f, sizeof f);
        _exit(n == static_cast<ssize_t>(sizeof f) ? 0 : 1);
    }
    close(fds[1]);
    LoadFigures f;
    const ssize_t n = read(fds[0], &f, sizeof f);
    close(fds[0]);
    int status = 0;
    waitpid(pid, &status, 0);
    if (n != static_cast<ssize_t>(sizeof f) || !WIFEXITED(status) || WEXITSTATUS(status) != 0) {
        throw std::runtime_error("the child that loads the series failed");
    }
    return f;
}

// Runs ITK's reader on the series; its one line of JSON holds the same figures.
std::optional<LoadFigures> loadWithItk(const std::filesystem::path& tool,
                                       const std::filesystem::path& dir) {
    const std::string command = "'" + tool.string() + "' '" + dir.string() + "'";
    FILE* pipe = popen(command.c_str(), "r");
    if (pipe == nullptr) {
        return std::nullopt;
    }
    std::string out;
    std::array<char, 512> buf{};
    while (std::fgets(buf.data(), static_cast<int>(buf.size()), pipe) != nullptr) {
        out += buf.data();
    }
    if (pclose(pipe) != 0) {
        throw std::runtime_error("ITK's reader failed on the series: " + command);
    }
    const auto j = nlohmann::json::parse(out);
    return LoadFigures{j.at("seconds").get<double>(), j.at("peak_bytes").get<double>(),
                       j.at("sum").get<double>()};
}

std::filesystem::path besideThisBinary(const char* name) {
    std::error_code ec;
    const auto self = std::filesystem::read_symlink("/proc/self/exe", ec);
    return ec ? std::filesystem::path(name) : self.parent_path() / name;
}

} // namespace

int main(int argc, char** argv) {
    bench::SyntheticCt ct;
    std::filesystem::path dir;
    std::filesystem::path jsonPath;
    bool keep = false;
    bool loadOnly = false;
    int repeat = 1;
    int bodyIterations = 100;
    std::filesystem::path itk = besideThisBinary("steerseg-itk-dicom-read");
    glm::ivec2 frame{320, 200};
    for (int n = 1; n < argc; ++n) {
        const std::string key = argv[n];
        const char* value = n + 1 < argc ? argv[n + 1] : nullptr;
        if (key == "--keep") {
            keep = true;
        } else if (key == "--load-only") {
            loadOnly = true;
        } else if (key == "--no-itk") {
            itk.clear();
        } else if (key == "--itk" && value != nullptr) {
            itk = value;
            ++n;
        } else if (key == "--repeat" && value != nullptr && std::atoi(value) > 0) {
            repeat = std::atoi(value);
            ++n;
        } else if (key == "--body-iterations" && value != nullptr && std::atoi(value) >= 0) {
            bodyIterations = std::atoi(value);
            ++n;
        } else if (key == "--size" && value != nullptr &&
                   std::sscanf(value, "%dx%dx%d", &ct.dims.x, &ct.dims.y, &ct.dims.z) == 3 &&
                   ct.dims.x >= 32 && ct.dims.y >= 32 && ct.dims.z >= 8) {
            ++n;
        } else if (key == "--frame" && value != nullptr &&
                   std::sscanf(value, "%dx%d", &frame.x, &frame.y) == 2 && frame.x > 0 &&
                   frame.y > 0) {
            ++n;
        } else if (key == "--dir" && value != nullptr) {
            dir = value;
            ++n;
        } else if (key == "--json" && value != nullptr) {
            jsonPath = value;
            ++n;
        } else {
            std::fprintf(stderr,
                         "usage: large_scan_bench [--size WxHxD (each >= 32, depth >= 8)] "
                         "[--dir DIR] [--keep] [--frame WxH] [--repeat N] [--body-iterations N] "
                         "[--itk PATH | --no-itk] [--load-only] [--json FILE]\n");
            return 2;
        }
    }
    const bool temporary = dir.empty();
    if (temporary) {
        char pattern[] = "/tmp/steerseg-large-XXXXXX";
        if (mkdtemp(pattern) == nullptr) {
            std::perror("large_scan_bench: mkdtemp");
            return 1;
        }
        dir = pattern;
    }
    nlohmann::ordered_json j;
    try {
        std::filesystem::create_directories(dir);
        std::setvbuf(stdout, nullptr, _IOLBF, 0);
        auto start = Clock::now();
        bench::writeSyntheticCt(ct, dir);
        const double voxelBytes = 2.0 * ct.dims.x * ct.dims.y * static_cast<double>(ct.dims.z);
        std::printf("series: %dx%dx%d int16 (%.0f MiB of voxels), written in %.1f s to %s\n",
                    ct.dims.x, ct.dims.y, ct.dims.z, voxelBytes / 1048576.0, secondsSince(start),
                    dir.c_str());
        j["dims"] = {ct.dims.x, ct.dims.y, ct.dims.z};
        j["voxel_bytes"] = voxelBytes;

        const bool withItk = !itk.empty() && access(itk.c_str(), X_OK) == 0;
        if (!withItk) {
            std::printf("ITK: %s, so no ITK column (configure with -DSTEERSEG_BENCH_ITK=ON after "
                        "tools/install-deps.sh --bench, or pass --itk PATH)\n",
                        itk.empty() ? "--no-itk" : (itk.string() + " not found").c_str());
        }
        // Alternately, so that a drift of the shared machine's load touches both.
        std::vector<LoadFigures> ours;
        std::vector<LoadFigures> theirs;
        for (int r = 0; r < repeat; ++r) {
            ours.push_back(loadInChild(dir));
            if (withItk) {
                theirs.push_back(*loadWithItk(itk, dir));
            }
        }
        const auto report = [&](const char* name, const std::vector<LoadFigures>& runs,
                                nlohmann::ordered_json& out) {
            std::string times;
            double best = runs.front().seconds;
            double peak = 0.0;
            for (const LoadFigures& f : runs) {
                times += (times.empty() ? "" : " / ") + std::to_string(f.seconds).substr(0, 5);
                best = std::min(best, f.seconds);
                peak = std::max(peak, f.peakBytes);
                out["seconds"].push_back(f.seconds);
            }
            std::printf("load %-22s %s s (best %.2f s), peak host memory %.0f MiB = %.2fx the "
                        "voxel bytes, sum of HU %.6g\n",
                        name, times.c_str(), best, peak / 1048576.0, peak / voxelBytes,
                        runs.front().sum);
            out["best_seconds"] = best;
            out["peak_bytes"] = peak;
            out["peak_over_voxel_bytes"] = peak / voxelBytes;
            out["sum"] = runs.front().sum;
        };
        report("steerseg (scan::readScan)", ours, j["load"]["steerseg"]);
        if (withItk) {
            report("ITK (GDCM series)", theirs, j["load"]["itk"]);
            const double ratio = j["load"]["itk"]["best_seconds"].get<double>() /
                                 j["load"]["steerseg"]["best_seconds"].get<double>();
            std::printf("load: steerseg %.2fx ITK's speed (best of %d each); same voxels: %s\n",
                        ratio, repeat, ours.front().sum == theirs.front().sum ? "yes" : "NO");
            j["load"]["steerseg_speed_over_itk"] = ratio;
            j["load"]["same_sum"] = ours.front().sum == theirs.front().sum;
        }
        if (loadOnly) {
            if (temporary && !keep) {
                std::filesystem::remove_all(dir);
            }
            if (!jsonPath.empty()) {
                std::ofstream(jsonPath) << j.dump(2) << "\n";
            }
            return 0;
        }

        scan::LoadedScan scan = scan::readScan(dir);
        auto context = platform::createOffscreenContext();
        std::printf("GL_RENDERER: %s\n", reinterpret_cast<const char*>(glGetString(GL_RENDERER)));
        j["renderer"] = reinterpret_cast<const char*>(glGetString(GL_RENDERER));
        start = Clock::now();
        const gpu::ScanTexture texture(scan.volume);
        glFinish();
        const double uploadSeconds = secondsSince(start);
        const double textureBytes = (texture.displaysExact() ? 4.0 : 6.0) * ct.dims.x * ct.dims.y *
                                    static_cast<double>(ct.dims.z);
        std::printf("scan texture: %.0f MiB (R32F%s), uploaded in %.1f s\n",
                    textureBytes / 1048576.0, texture.displaysExact() ? "" : " + R16F display copy",
                    uploadSeconds);
        j["upload_seconds"] = uploadSeconds;
        j["scan_texture_bytes"] = textureBytes;

        start = Clock::now();
        solver::LevelSetSolver solver(texture);
        glFinish();
        const double solverSetupSeconds = secondsSince(start);
        std::printf("solver: set up in %.2f s, host memory now %.0f MiB (peak %.0f MiB)\n",
                    solverSetupSeconds, bench::statusBytes("VmRSS") / 1048576.0,
                    bench::statusBytes("VmHWM") / 1048576.0);
        j["solver_setup_seconds"] = solverSetupSeconds;
        solver.setParams({120.0F, 45.0F, 0.8F});
        solver.addSphere({glm::vec3(ct.lesionCentre), 3.0F});
        start = Clock::now();
        const model::StepResult r = solver.runUntilConverged(5000);
        const double solveSeconds = secondsSince(start);
        const model::SolverStats st = solver.stats();
        std::size_t inside = 0;
        for (const std::uint8_t m : solver.readMask()) {
            inside += m;
        }
        std::printf("solver: %d iterations in %.1f s (%.1f it/s)%s, peak %u of %u bricks active, "
                    "pool %.1f MiB (peak %.1f MiB; dense phi would be %.0f MiB)\n",
                    r.iterations, solveSeconds, r.iterations / solveSeconds,
                    r.converged ? ", converged" : ", NOT converged", st.peakActiveBricks,
                    st.totalBricks, static_cast<double>(st.levelSetBytes) / 1048576.0,
                    static_cast<double>(st.peakLevelSetBytes) / 1048576.0,
                    static_cast<double>(st.densePhiBytes) / 1048576.0);
        std::printf("lesion: %zu voxels inside, %zu true; peak active %.2f%% of the bricks, pool "
                    "at its peak %.2fx the peak active bricks' phi + page table\n",
                    inside, ct.lesionVoxels, 100.0 * st.peakActiveBricks / st.totalBricks,
                    static_cast<double>(st.peakLevelSetBytes) /
                        (st.peakActiveBricks * 2048.0 + st.totalBricks * 4.0));
        j["iterations"] = r.iterations;
        j["solve_seconds"] = solveSeconds;
        j["iterations_per_second"] = r.iterations / solveSeconds;
        j["converged"] = r.converged;
        j["peak_active_bricks"] = st.peakActiveBricks;
        j["total_bricks"] = st.totalBricks;
        j["pool_bytes"] = st.levelSetBytes;
        j["peak_pool_bytes"] = st.peakLevelSetBytes;
        j["inside_voxels"] = inside;
        j["true_voxels"] = ct.lesionVoxels;

        start = Clock::now();
        render::Renderer renderer(scan.volume, texture);
        glFinish();
        const double setupSeconds = secondsSince(start);
        render::ViewParams p = renderer.defaultParams(render::ViewKind::Volume3d, frame);
        p.transfer = render::transferPreset(render::TfPreset::CtSoftTissue, scan.volume.stats());
        const solver::BrickPoolView view = solver.poolView();
        start = Clock::now();
        renderer.render(p, &view); // compiles the ray caster's variant
        glFinish();
        const double firstFrameSeconds = secondsSince(start);
        start = Clock::now();
        renderer.render(p, &view);
        glFinish();
        const double frameSeconds = secondsSince(start);
        std::printf("renderer: set up in %.1f s (gradient texture: %s), 3D frame + surface %dx%d "
                    "in %.2f s (the first, with its shader's compilation, %.2f s)\n",
                    setupSeconds,
                    renderer.precomputedGradient() ? "yes" : "no, over its 1 GiB budget", frame.x,
                    frame.y, frameSeconds, firstFrameSeconds);
        j["renderer_setup_seconds"] = setupSeconds;
        j["gradient_texture"] = renderer.precomputedGradient();
        j["frame_seconds"] = frameSeconds;
        j["first_frame_seconds"] = firstFrameSeconds;

        if (bodyIterations > 0) {
            // A front the size of a large organ: a sphere of a fifth of the scan's smallest side
            // in the body's soft tissue, stepped a fixed number of iterations.
            solver::LevelSetSolver body(texture);
            body.setParams({40.0F, 30.0F, 0.8F});
            const float radius =
                0.2F * static_cast<float>(std::min({ct.dims.x, ct.dims.y, ct.dims.z}));
            body.addSphere({glm::vec3(ct.dims) * 0.5F, radius});
            body.step(16); // the band settles and the pool finds its size
            start = Clock::now();
            const model::StepResult b = body.step(bodyIterations);
            const double bodySeconds = secondsSince(start);
            const model::SolverStats bs = body.stats();
            std::printf("solver, large front (sphere r = %.0f voxels in the body): %d iterations "
                        "in %.1f s (%.1f it/s), %u of %u bricks active (%.2f%%), pool %.1f MiB "
                        "(peak %.1f MiB) = %.2fx the active bricks' phi + page table\n",
                        static_cast<double>(radius), b.iterations, bodySeconds,
                        b.iterations / bodySeconds, bs.activeBricks, bs.totalBricks,
                        100.0 * bs.activeBricks / bs.totalBricks,
                        static_cast<double>(bs.levelSetBytes) / 1048576.0,
                        static_cast<double>(bs.peakLevelSetBytes) / 1048576.0,
                        static_cast<double>(bs.levelSetBytes) /
                            (bs.activeBricks * 2048.0 + bs.totalBricks * 4.0));
            j["body"] = {{"radius", radius},
                         {"iterations", b.iterations},
                         {"seconds", bodySeconds},
                         {"iterations_per_second", b.iterations / bodySeconds},
                         {"active_bricks", bs.activeBricks},
                         {"pool_bytes", bs.levelSetBytes},
                         {"peak_pool_bytes", bs.peakLevelSetBytes}};
        }
    } catch (const std::exception& e) {
        std::fprintf(stderr, "large_scan_bench: %s\n", e.what());
        if (temporary && !keep) {
            std::filesystem::remove_all(dir);
        }
        return 1;
    }
    if (temporary && !keep) {
        std::filesystem::remove_all(dir);
    }
    if (!jsonPath.empty()) {
        std::ofstream(jsonPath) << j.dump(2) << "\n";
    }
    return 0;
}
