// GPU solver against the CPU reference on real CT tumours, and (printed, not asserted) against
// the expert contour. Scans are cropped to the expert mask's bounding box plus a margin so the
// test stays small on llvmpipe.
//
// Parameters come from the expert mask the way an operator would probe the tumour (Lefohn et
// al. set T and eps from the mean and spread of probed values): seed at the mask's centroid with
// half the radius of the mask's equivalent ball (so it starts inside the tumour), T = mean HU
// inside the mask, eps = 2 standard deviations (1 sd leaves a third of the tumour's noisy voxels
// with a negative speed), alpha = 0.7 (some smoothing against CT noise).
#include "scan/scan_reader.hpp"
#include "solver/level_set_solver.hpp"
#include "solver/reference_solver.hpp"
#include "support/gpu_fixture.hpp"
#include "support/solver_test_support.hpp"
#include "support/test_data.hpp"

#include <algorithm>
#include <cmath>
#include <gtest/gtest.h>

namespace steerseg::test {
using namespace steerseg::solver; // the solver under test
using namespace steerseg::model;
namespace {

class SolverRealScanTest : public GpuTest {};

struct Case {
    std::vector<float> values;
    std::vector<std::uint8_t> expert;
    glm::ivec3 dims;
    LevelSetParams params;
    Sphere seed;
};

Case cropAroundMask(const Volume& scan, const Volume& maskVolume, int margin) {
    const glm::ivec3 d = scan.dims();
    EXPECT_EQ(maskVolume.dims(), d);
    glm::ivec3 lo = d;
    glm::ivec3 hi(-1);
    const std::vector<float> all = scan.realValues();
    for (int k = 0; k < d.z; ++k) {
        for (int j = 0; j < d.y; ++j) {
            for (int i = 0; i < d.x; ++i) {
                if (maskVolume.storedAt(voxelIndex(d, i, j, k)) != 0.0) {
                    lo = glm::min(lo, glm::ivec3(i, j, k));
                    hi = glm::max(hi, glm::ivec3(i, j, k));
                }
            }
        }
    }
    lo = glm::max(lo - margin, glm::ivec3(0));
    hi = glm::min(hi + margin, d - 1);
    Case c;
    c.dims = hi - lo + 1;
    double sum = 0.0;
    double sum2 = 0.0;
    std::size_t n = 0;
    glm::dvec3 centroid(0.0);
    for (int k = lo.z; k <= hi.z; ++k) {
        for (int j = lo.y; j <= hi.y; ++j) {
            for (int i = lo.x; i <= hi.x; ++i) {
                const float v = all[voxelIndex(d, i, j, k)];
                const bool in = maskVolume.storedAt(voxelIndex(d, i, j, k)) != 0.0;
                c.values.push_back(v);
                c.expert.push_back(in ? 1 : 0);
                if (in) {
                    sum += static_cast<double>(v);
                    sum2 += static_cast<double>(v) * static_cast<double>(v);
                    centroid += glm::dvec3(i - lo.x, j - lo.y, k - lo.z);
                    ++n;
                }
            }
        }
    }
    const double mean = sum / static_cast<double>(n);
    const double sd = std::sqrt(std::max(0.0, sum2 / static_cast<double>(n) - mean * mean));
    c.params = {static_cast<float>(mean), static_cast<float>(2.0 * sd), 0.7F};
    c.seed = {glm::vec3(centroid / static_cast<double>(n)),
              static_cast<float>(0.5 * equivalentRadius(c.expert))};
    return c;
}

void runCase(const std::filesystem::path& image, const std::filesystem::path& mask,
             const char* name) {
    const Case c = cropAroundMask(scan::readScan(image).volume, scan::readScan(mask).volume, 6);
    std::printf("%s: crop %d x %d x %d, T %.1f eps %.1f alpha %.2f, seed (%.1f %.1f %.1f) r %.1f\n",
                name, c.dims.x, c.dims.y, c.dims.z, static_cast<double>(c.params.T),
                static_cast<double>(c.params.eps), static_cast<double>(c.params.alpha),
                static_cast<double>(c.seed.centre.x), static_cast<double>(c.seed.centre.y),
                static_cast<double>(c.seed.centre.z), static_cast<double>(c.seed.radius));

    // Agreement with the reference over the first iterations (asserted).
    constexpr int kCompared = 40;
    constexpr int kMaxIterations = 80; // the expert comparison stops here if not converged
    constexpr int kCheckEvery = 40;
    LevelSetSolver gpu(c.values, c.dims);
    ReferenceSolver cpu(c.values, c.dims);
    gpu.addSphere(c.seed);
    cpu.addSphere(c.seed);
    gpu.setParams(c.params);
    cpu.setParams(c.params);
    gpu.step(kCompared);
    cpu.step(kCompared);
    const auto gpuMask = gpu.readMask();
    const auto cpuMask = cpu.mask();
    EXPECT_GE(dice(gpuMask, cpuMask), 0.99);
    EXPECT_EQ(differencesOffSurface(c.dims, gpuMask, cpuMask), 0U);

    // Against the expert (printed): best Dice seen and Dice at convergence.
    double best = dice(gpuMask, c.expert);
    int bestIteration = kCompared;
    int iteration = kCompared;
    while (!gpu.converged() && iteration < kMaxIterations) {
        iteration += gpu.step(kCheckEvery).iterations;
        const double d = dice(gpu.readMask(), c.expert);
        if (d > best) {
            best = d;
            bestIteration = iteration;
        }
    }
    std::printf("%s: Dice vs expert %.3f at %s after %d iterations (t = %.2f); best %.3f at "
                "iteration %d\n",
                name, dice(gpu.readMask(), c.expert), gpu.converged() ? "convergence" : "the cap",
                iteration, static_cast<double>(gpu.stats().evolvedTime), best, bestIteration);
}

TEST_F(SolverRealScanTest, ThighSarcomaCtMatchesReference) {
    STEERSEG_REQUIRE_DATA(image, "thigh-sarcoma-sts001/STS_001_CT_image.nii.gz");
    STEERSEG_REQUIRE_DATA(mask, "thigh-sarcoma-sts001/STS_001_CT_mask.nii.gz");
    runCase(image, mask, "sts001 CT");
}

TEST_F(SolverRealScanTest, LungCtMatchesReference) {
    STEERSEG_REQUIRE_DATA(image, "lung-ct-ibsi/nifti/image.nii.gz");
    STEERSEG_REQUIRE_DATA(mask, "lung-ct-ibsi/nifti/mask.nii.gz");
    runCase(image, mask, "lung CT");
}

} // namespace
} // namespace steerseg::test
